/**
 * @file parameter_file.h
 * Reading a .prm file robustly: `include` lines expanded here (relative to the including file,
 * cycles and directories refused with the include chain named), a UTF-8 byte-order mark
 * dropped, empty files refused, command-line overrides (`--set "Section/Entry=value"`) parsed
 * exactly like lines of the file, and every error reported as "file:line: [in subsection 'X':]
 * message".
 */
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <map>
#include <string>
#include <vector>

namespace ausroll
{
  /** Where one line of an expanded parameter text comes from. */
  struct LineOrigin
  {
    std::string  file; ///< file name as given (or "--set '...'" for an override)
    unsigned int line; ///< 1-based line in that file (0 for an override)
  };

  /** A parameter file with its includes expanded, and the origin of every line. */
  struct ParameterText
  {
    std::string             text;   ///< the expanded lines, '\n'-terminated
    std::vector<LineOrigin> origin; ///< origin[i]: where line i+1 of @ref text comes from
  };

  /**
   * Read @p filename and expand its `include` lines recursively (a relative path is looked for
   * next to the including file first, then in the working directory). InputError for a missing
   * or unreadable file, a directory, an include cycle (the chain is named), more than 32 nested
   * includes, or a file without a single entry (empty or only comments).
   */
  ParameterText expand_parameter_file(const std::string &filename);

  /** One `--set "Section/Sub/Entry=value"` argument. */
  struct ParameterOverride
  {
    std::vector<std::string> subsections; ///< "Section", "Sub"
    std::string              entry;       ///< "Entry"
    std::string              value;       ///< "value"
    std::string              argument;    ///< the argument as given
  };

  /** Split @p argument "Section/Entry=value"; UsageError if it does not have that form. */
  ParameterOverride parse_override(const std::string &argument);

  /**
   * Parse @p text into @p prm, then the @p overrides (each validated like a line of the file:
   * an unknown entry or a value not matching its pattern is an InputError naming the argument).
   * An unknown entry listed in @p moved_entries (old full path "Section/Entry" -> where it is
   * now) gets the message "`Section/Entry` moved to <new path>" after the file and line.
   */
  void parse_parameter_text(dealii::ParameterHandler                 &prm,
                            const ParameterText                      &text,
                            const std::vector<ParameterOverride>     &overrides,
                            const std::map<std::string, std::string> &moved_entries = {});

  /** Every entry of @p prm as "Section/Sub/Entry" -> value (the parsed values). */
  std::map<std::string, std::string> flatten_parameters(const dealii::ParameterHandler &prm);

  /**
   * Refuse numbers no ausroll entry can mean: a literal of magnitude above 1e30 (lengths are mm,
   * stresses MPa; such values overflow in products), inf or nan, in any entry value (numbers,
   * points, expressions). The InputError names the entry.
   */
  void check_number_magnitudes(const std::map<std::string, std::string> &entries);

  /** The "Additional information" of a deal.II exception on one line, without boilerplate. */
  std::string user_message(const dealii::ExceptionBase &e);
} // namespace ausroll
