/**
 * @file property_table.h
 * A material property that depends on temperature: a constant or a piecewise-linear table.
 */
#pragma once

#include <string>
#include <vector>

namespace ausroll::material
{
  /**
   * A property p(T) given in a `.prm` entry as
   * - a number: constant (`45`);
   * - a table of temperature: value pairs, temperatures strictly increasing
   *   (`20: 45, 300: 40, 600: 34`): linear between the rows, constant beyond the first and the
   *   last row (no extrapolation);
   * - `file: NAME.csv`: the same table as a CSV file of two columns (temperature, value; a first
   *   line that is not numeric is a header), NAME relative to the `.prm` file's folder.
   * Units are those of the entry that holds the table (temperature in the scene's unit).
   */
  class PropertyTable
  {
  public:
    /** A constant property. */
    PropertyTable(const double value = 0.); // NOLINT: a number is a constant table

    /**
     * Parse @p text (see the class description) for entry @p entry (its full path, for messages);
     * @p input_directory resolves `file:` names. With @p positive every value must be > 0,
     * with @p non_negative >= 0; throws InputError naming the entry otherwise. @p argument
     * names the table's first column in the messages (a table in depth: "depth").
     */
    static PropertyTable parse(const std::string &text,
                               const std::string &entry,
                               const std::string &input_directory,
                               const bool         positive,
                               const bool         non_negative = false,
                               const std::string &argument = "temperature");

    /** p(T). */
    double value(const double temperature) const;

    /** dp/dT (0 beyond the table and on a constant). */
    double derivative(const double temperature) const;

    /** True if the property does not depend on temperature. */
    bool is_constant() const { return temperatures.size() <= 1; }

    /** The temperatures of the rows (one row: a constant). */
    const std::vector<double> &row_temperatures() const { return temperatures; }

    /** Smallest and largest value of the table. */
    double min_value() const;
    double max_value() const;

  private:
    std::vector<double> temperatures; ///< strictly increasing (one entry: constant)
    std::vector<double> values;       ///< p at each temperature
  };
} // namespace ausroll::material
