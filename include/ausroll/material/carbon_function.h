/**
 * @file carbon_function.h
 * A material function of the carbon content given as an expression of C (Ms(C), the volume
 * changes of `Phases`), memoised: the carbon of a material point never changes, so the same C
 * is evaluated at every call of that point.
 */
#pragma once

#include <deal.II/base/function_parser.h>

#include <cstdint>
#include <memory>
#include <string>

namespace ausroll::material
{
  /**
   * f(C) of an expression in the variable C (wt%), checked finite over 0 <= C <= 2.1.
   *
   * value() returns exactly the value of the expression (the same muparser evaluation) but
   * remembers it: a per-thread direct-mapped table of `slots` entries keyed by this function's
   * serial number and the bit pattern of C. A hit returns the stored double, a miss evaluates
   * and stores, so the result is bit-identical to evaluating every time. A uniform carbon content
   * always hits; a profile hits as long as its distinct carbon values per thread fit the table
   * (4096 entries per thread, 96 KiB, shared by all functions; a collision only costs an
   * evaluation).
   */
  class CarbonFunction
  {
  public:
    /** Parse @p expression; InputError naming @p entry if it does not parse or is not finite. */
    CarbonFunction(const std::string &expression, const std::string &entry);

    /** f(@p C), exactly the expression's value. */
    double value(const double C) const;

    /** The expression's value without the memo (for the measurements of the cost). */
    double evaluate(const double C) const;

    /** Entries of the per-thread table. */
    static constexpr unsigned int slots = 4096;

  private:
    std::unique_ptr<dealii::FunctionParser<1>> parser;
    std::uint64_t                              serial; ///< unique among all CarbonFunctions
  };
} // namespace ausroll::material
