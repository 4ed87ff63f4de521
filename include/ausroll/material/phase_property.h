/**
 * @file phase_property.h
 * A property of a product phase (the yield stress and hardening modulus of martensite or
 * bainite): absent, a number or table in the temperature, or an expression of the carbon content
 * C and the temperature T.
 */
#pragma once

#include <ausroll/material/carbon_function.h>
#include <ausroll/material/property_table.h>

#include <memory>
#include <string>

namespace ausroll::material
{
  /**
   * p(C, T) of one `Phases` entry:
   * - empty: not given (given() is false; the caller decides what that means);
   * - a number, a table `T1: p1, T2: p2, ...` or `file: NAME.csv` (PropertyTable): p(T), the
   *   same for every carbon content;
   * - anything else: an expression of C (wt%) and T (CarbonFunction with the temperature, memoised
   *   per thread), e.g. `413 + 1720*sqrt(C)`; checked finite and of the required sign over
   *   0 <= C <= 2.1, 0 <= T <= 1000.
   * A text is a table if it starts with `file:` or holds only digits, `.`, `e`, `E`, `+`, `-`,
   * `:`, `,` and blanks.
   */
  class PhaseProperty
  {
  public:
    /** Not given. */
    PhaseProperty() = default;

    /** The table @p table (given; for tests and callers that build the table themselves). */
    PhaseProperty(const PropertyTable &table); // NOLINT: a table is a property

    /**
     * Parse @p text for the entry @p entry (its full path, for messages); @p directory resolves
     * `file:` tables. @p positive: every value > 0, else >= 0; InputError naming the entry.
     */
    static PhaseProperty parse(const std::string &text,
                               const std::string &entry,
                               const std::string &directory,
                               const bool         positive);

    /** True unless the entry was empty. */
    bool given() const { return is_given; }

    /** True if the value depends on the carbon content (an expression). */
    bool is_expression() const { return static_cast<bool>(expression); }

    /** p(@p C, @p T) (0 if not given). */
    double value(const double C, const double T) const
    {
      if (expression)
        return expression->value(C, T);
      return is_given ? table.value(T) : 0.;
    }

  private:
    bool                                  is_given = false;
    PropertyTable                         table;      ///< p(T) (a number or table)
    std::shared_ptr<const CarbonFunction> expression; ///< p(C, T) (an expression)
  };
} // namespace ausroll::material
