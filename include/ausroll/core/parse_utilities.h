/**
 * @file parse_utilities.h
 * Small helpers that turn .prm strings into numbers, points and lists, and report a bad value
 * with the full name of the entry.
 */
#pragma once

#include <deal.II/base/point.h>

#include <string>
#include <utility>
#include <vector>

namespace ausroll
{
  /** Split @p text at @p delimiter and trim blanks around each piece (empty pieces dropped). */
  std::vector<std::string> split_and_trim(const std::string &text, const char delimiter);

  /** Parse a number; throw InputError naming @p entry if @p text is not one. */
  double parse_double(const std::string &text, const std::string &entry);

  /** Parse a comma-separated list of numbers. */
  std::vector<double> parse_double_list(const std::string &text, const std::string &entry);

  /** Parse a comma-separated list of non-negative integers. */
  std::vector<unsigned int> parse_unsigned_list(const std::string &text, const std::string &entry);

  /**
   * @p text shortened for a message: at most 80 characters, with the full length stated when
   * cut ("t*(1+t*(1+ ... (180000 characters)").
   */
  std::string abbreviate(const std::string &text);

  /**
   * InputError naming @p entry if @p expression is longer than the expression parser accepts
   * (20000 characters): "expression too long".
   */
  void require_expression_length(const std::string &expression, const std::string &entry);

  /**
   * Refuse a label that names history columns and files (a die's `Name`, a monitor point, a line
   * probe) unless it is 1 to 64 letters, digits, '_', '-' or '.', and not "." or "..": a comma
   * would shift every column of history.csv, a '/' or ".." would put a file elsewhere or
   * nowhere. InputError "<entry>: '<name>' must be a single word of ...".
   */
  void require_label(const std::string &name, const std::string &entry);

  /**
   * Refuse a name that appears twice in @p names (labels of one list, e.g. the monitor points):
   * InputError "<entry>: the name '<name>' is used twice ...".
   */
  void require_unique_labels(const std::vector<std::string> &names, const std::string &entry);

  /** Parse "x, y[, z]" into a point with exactly dim coordinates. */
  template <int dim>
  dealii::Point<dim> parse_point(const std::string &text, const std::string &entry);

  /**
   * Parse a list of named points "name: x, y; name2: x, y" (used by `Postprocess/Monitor points`).
   */
  template <int dim>
  std::vector<std::pair<std::string, dealii::Point<dim>>>
  parse_named_points(const std::string &text, const std::string &entry);
} // namespace ausroll
