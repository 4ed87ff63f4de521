/**
 * @file parameter_documentation.h
 * `ausroll --print-parameters`: every parameter with default and documentation.
 */
#pragma once

#include <ostream>
#include <string>

namespace ausroll::io
{
  /**
   * Print all scene parameters to @p out, as a commented .prm file (@p format = "prm") or as the
   * Markdown reference doc/parameters.md (@p format = "markdown").
   */
  void print_parameters(std::ostream &out, const std::string &format);
} // namespace ausroll::io
