/**
 * @file bainite_kinetics.h
 * Isothermal bainite kinetics from a TTT diagram (JMAK) made non-isothermal by the additivity
 * rule.
 */
#pragma once

#include <ausroll/material/property_table.h>

#include <string>

namespace ausroll::material
{
  /**
   * Bainite from the TTT diagram of the steel: at each temperature T of the bainite range the
   * times t_s(T) and t_f(T) at which 1 % and 99 % of the austenite have transformed in an
   * isothermal hold give the Johnson-Mehl-Avrami-Kolmogorov law xi(t) = 1 - exp(-k t^n) with
   *
   *   n(T) = ln(ln 0.01 / ln 0.99) / ln(t_f / t_s),   k(T) = -ln(0.99) / t_s^n,
   *
   * xi the transformed share of the austenite available. Non-isothermal paths follow the
   * additivity rule (Scheil 1935 for the incubation, Avrami 1940 and Cahn 1956 for the growth):
   * a step of length dt at temperature T starts from the fictitious time t* at which an
   * isothermal hold at T would have reached the current xi, t* = (-ln(1 - xi) / k)^(1/n), and
   * ends at xi = 1 - exp(-k (t* + dt)^n). For an isothermal hold this is exact whatever the steps
   * are; outside the table's temperature range nothing transforms (the rows span the bainite
   * range, between Ms and the bainite start temperature). t_s and t_f are PropertyTables in T
   * (linear between rows: give rows as dense as the curvature of the C-curve needs).
   */
  class BainiteKinetics
  {
  public:
    /** No bainite (empty tables). */
    BainiteKinetics() = default;

    /**
     * Kinetics from the tables @p start (t_s) and @p finish (t_f) written as PropertyTable text
     * (`T1: t1, T2: t2, ...` or `file: NAME.csv`); both empty: no bainite. Throws InputError
     * naming @p start_entry / @p finish_entry if only one is given, if they are not tables over
     * the same temperatures, or if t_f <= t_s at a row.
     */
    BainiteKinetics(const std::string &start,
                    const std::string &finish,
                    const std::string &start_entry,
                    const std::string &finish_entry,
                    const std::string &input_directory);

    /** True if bainite can form. */
    bool active() const { return enabled; }

    /** Avrami exponent n at @p T (inside the range). */
    double exponent(const double T) const;

    /** Rate constant k at @p T (1/s^n, inside the range). */
    double rate(const double T) const;

    /** k at @p T for its exponent @p n (= exponent(T), computed once by the caller). */
    double rate(const double T, const double n) const;

    /** True if @p T lies in the bainite range of the tables. */
    bool in_range(const double T) const { return enabled && T >= lowest && T <= highest; }

    /** Share xi of the available austenite transformed after a step of length @p dt at @p T,
        starting from @p xi_old (the additivity rule above). */
    double advance(const double xi_old, const double T, const double dt) const;

  private:
    bool          enabled = false;
    PropertyTable start_time;   ///< t_s(T), s
    PropertyTable finish_time;  ///< t_f(T), s
    double        lowest = 0.;  ///< first temperature of the tables
    double        highest = 0.; ///< last temperature of the tables
  };
} // namespace ausroll::material
