/**
 * @file carbon_function.h
 * A material function of the carbon content given as an expression of C (Ms(C), the volume
 * changes of `Phases`) or of C and the temperature T (the yield stress and hardening modulus of
 * martensite), memoised: the carbon of a material point never changes, and its temperature
 * stays the same through the Newton iterations of a step, so the same arguments are evaluated
 * at every call of that point.
 */
#pragma once

#include <deal.II/base/function_parser.h>

#include <cstdint>
#include <memory>
#include <string>

namespace ausroll::material
{
  /**
   * f(C) of an expression in the variable C (wt%), checked finite over 0 <= C <= 2.1; or, made
   * with `temperature`, f(C, T) of an expression in C and T (the scene's temperature unit),
   * checked finite over 0 <= C <= 2.1 and 0 <= T <= 1000 (value(C, T)).
   *
   * value() returns exactly the value of the expression (the same muparser evaluation) but
   * remembers it: a per-thread direct-mapped table of `slots` entries keyed by this function's
   * serial number and the bit pattern of C. A hit returns the stored double, a miss evaluates
   * and stores, so the result is bit-identical to evaluating every time. A uniform carbon content
   * always hits; a profile hits as long as its distinct carbon values per thread fit the table
   * (4096 entries per thread, 128 KiB, shared by all functions; a collision only costs an
   * evaluation).
   */
  class CarbonFunction
  {
  public:
    /** Parse @p expression, in C alone or, with @p temperature, in C and T; InputError naming
        @p entry if it does not parse or is not finite. */
    CarbonFunction(const std::string &expression,
                   const std::string &entry,
                   const bool         temperature = false);

    /** f(@p C), exactly the expression's value (a function of C alone). */
    double value(const double C) const;

    /** f(@p C, @p T), exactly the expression's value (a function made with `temperature`). */
    double value(const double C, const double T) const;

    /** The expression's value without the memo (for the measurements of the cost). */
    double evaluate(const double C) const;

    /** f(@p C, @p T) without the memo. */
    double evaluate(const double C, const double T) const;

    /** True if the expression is one of C and T. */
    bool uses_temperature() const { return static_cast<bool>(parser_ct); }

    /** Entries of the per-thread table. */
    static constexpr unsigned int slots = 4096;

  private:
    std::unique_ptr<dealii::FunctionParser<1>> parser;    ///< f(C) (null for f(C, T))
    std::unique_ptr<dealii::FunctionParser<2>> parser_ct; ///< f(C, T) (null for f(C))
    std::uint64_t                              serial;    ///< unique among all CarbonFunctions
  };
} // namespace ausroll::material
