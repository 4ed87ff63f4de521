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
   * Throw an InputError with message "<entry>: <what>" unless @p condition holds.
   */
  inline void require(const bool condition, const std::string &entry, const std::string &what)
  {
    if (!condition)
      throw InputError(entry + ": " + what);
  }
} // namespace ausroll
