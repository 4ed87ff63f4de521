/**
 * @file phase_property.cc
 * Properties of the product phases (see phase_property.h).
 */
#include <ausroll/core/exceptions.h>
#include <ausroll/core/parse_utilities.h>
#include <ausroll/material/phase_property.h>

#include <sstream>

namespace ausroll::material
{
  PhaseProperty::PhaseProperty(const PropertyTable &table_in)
      : is_given(true)
      , table(table_in)
  {
  }

  PhaseProperty PhaseProperty::parse(const std::string &text,
                                     const std::string &entry,
                                     const std::string &directory,
                                     const bool         positive)
  {
    PhaseProperty property;
    const auto    first = text.find_first_not_of(" \t");
    if (first == std::string::npos)
      return property;
    property.is_given = true;
    const bool table = text.compare(first, 5, "file:") == 0
                       || text.find_first_not_of("0123456789.eE+-:, \t") == std::string::npos;
    if (table)
    {
      property.table = PropertyTable::parse(text, entry, directory, positive, !positive);
      return property;
    }
    property.expression = std::make_shared<const CarbonFunction>(text, entry, true);
    for (unsigned int i = 0; i <= 21; ++i)
      for (unsigned int j = 0; j <= 20; ++j)
      {
        const double value = property.expression->evaluate(0.1 * i, 50. * j);
        if (positive ? !(value > 0.) : !(value >= 0.))
        {
          std::ostringstream message;
          message << entry << ": '" << abbreviate(text) << "' is " << value << " at C = " << 0.1 * i
                  << ", T = " << 50 * j << " (must be " << (positive ? "positive" : "non-negative")
                  << " for 0 <= C <= 2.1, 0 <= T <= 1000)";
          throw InputError(message.str());
        }
      }
    return property;
  }
} // namespace ausroll::material
