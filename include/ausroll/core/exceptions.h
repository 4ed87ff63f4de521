/**
 * @file exceptions.h
 * Exceptions that carry a message meant for the user of ausroll (not for a developer).
 */
#pragma once

#include <stdexcept>
#include <string>

namespace ausroll
{
  /**
   * Invalid input: a bad value, an inconsistent combination of parameters, a missing file.
   * The message names the full parameter path (e.g. "Geometry/Quarter ring/Inner radius") or the
   * file. main() prints it and exits with status 2.
   */
  class InputError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /**
   * A run that cannot continue: a load step that does not converge after the allowed cutbacks,
   * an inverted element that cannot be cured, ... main() prints the message and exits with status
   * 3; everything written before stays valid.
   */
  class RunFailure : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /**
   * A command line that cannot be understood (unknown option, malformed `--set`): main() prints
   * the message and the usage and exits with status 1.
   */
  class UsageError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /**
   * An invalid value found by a builder that knows only the entry's own name (e.g. the
   * die-surface factory: "Pressure angle"), not its subsection: the caller catches it and
   * reports `<subsection path><entry>: <what>`.
   */
  class EntryError : public InputError
  {
  public:
    EntryError(const std::string &entry, const std::string &what)
        : InputError(entry + ": " + what)
        , entry_name(entry)
        , reason(what)
    {
    }
    /** The entry's name within its subsection. */
    const std::string &entry() const { return entry_name; }
    /** What is wrong with its value. */
    const std::string &what_is_wrong() const { return reason; }

  private:
    std::string entry_name;
    std::string reason;
  };

  /**
   * Throw an InputError with message "<entry>: <what>" unless @p condition holds.
   */
  inline void require(const bool condition, const std::string &entry, const std::string &what)
  {
    if (!condition)
      throw InputError(entry + ": " + what);
  }
} // namespace ausroll
