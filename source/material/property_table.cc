#include <ausroll/core/exceptions.h>
#include <ausroll/core/parse_utilities.h>
#include <ausroll/material/property_table.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <sys/stat.h>

namespace ausroll::material
{
  PropertyTable::PropertyTable(const double value)
      : temperatures{0.}
      , values{value}
  {
  }

  namespace
  {
    /** Rows "T: value" of an inline table. */
    void parse_inline_rows(const std::string   &text,
                           const std::string   &entry,
                           std::vector<double> &t,
                           std::vector<double> &v)
    {
      for (const std::string &row : split_and_trim(text, ','))
      {
        const auto colon = row.find(':');
        if (colon == std::string::npos)
          throw InputError(entry + ": table row '" + abbreviate(row)
                           + "' is not 'temperature: value' (write a single number for a "
                             "constant, or rows 'T1: v1, T2: v2, ...')");
        t.push_back(parse_double(row.substr(0, colon), entry));
        v.push_back(parse_double(row.substr(colon + 1), entry));
      }
    }

    /** Rows "T, value" of a CSV file (a non-numeric first line is a header). */
    void read_csv_rows(const std::string   &file,
                       const std::string   &entry,
                       const std::string   &argument,
                       std::vector<double> &t,
                       std::vector<double> &v)
    {
      struct stat info;
      if (stat(file.c_str(), &info) != 0)
        throw InputError(entry + ": cannot open table file '" + file + "'");
      if (!S_ISREG(info.st_mode))
        throw InputError(entry + ": table file '" + file + "' is not a regular file");
      if (info.st_size > (1 << 20))
        throw InputError(entry + ": table file '" + file + "' is larger than 1 MiB");
      std::ifstream in(file);
      if (!in)
        throw InputError(entry + ": cannot read table file '" + file + "'");
      std::string  line;
      unsigned int number = 0;
      while (std::getline(in, line))
      {
        ++number;
        const std::vector<std::string> cells = split_and_trim(line, ',');
        if (cells.empty() || cells[0][0] == '#')
          continue;
        const std::string where = entry + " (" + file + ", line " + std::to_string(number) + ")";
        if (cells.size() != 2)
          throw InputError(where + ": expected two columns '" + argument + ", value'");
        char *end = nullptr;
        std::strtod(cells[0].c_str(), &end);
        if (t.empty() && number == 1 && *end != '\0')
          continue; // header
        t.push_back(parse_double(cells[0], where));
        v.push_back(parse_double(cells[1], where));
      }
    }
  } // namespace

  PropertyTable PropertyTable::parse(const std::string &text,
                                     const std::string &entry,
                                     const std::string &input_directory,
                                     const bool         positive,
                                     const bool         non_negative,
                                     const std::string &argument)
  {
    PropertyTable table;
    table.temperatures.clear();
    table.values.clear();
    const std::vector<std::string> pieces = split_and_trim(text, ',');
    if (pieces.empty())
      throw InputError(entry + ": empty (write a number or a table 'T1: v1, T2: v2, ...')");
    if (text.find("file:") != std::string::npos)
    {
      std::string name = text.substr(text.find("file:") + 5);
      name = split_and_trim(name, '\n').empty() ? "" : split_and_trim(name, '\n')[0];
      if (name.empty())
        throw InputError(entry + ": 'file:' needs a file name");
      const std::string path
          = (name[0] == '/' || input_directory.empty()) ? name : input_directory + "/" + name;
      read_csv_rows(path, entry, argument, table.temperatures, table.values);
      if (table.values.empty())
        throw InputError(entry + ": table file '" + path + "' has no rows");
    }
    else if (pieces.size() == 1 && pieces[0].find(':') == std::string::npos)
    {
      table.temperatures.push_back(0.);
      table.values.push_back(parse_double(pieces[0], entry));
    }
    else
      parse_inline_rows(text, entry, table.temperatures, table.values);

    for (unsigned int i = 1; i < table.temperatures.size(); ++i)
      if (!(table.temperatures[i] > table.temperatures[i - 1]))
        throw InputError(entry + ": the " + argument + "s of the table must increase strictly (row "
                         + std::to_string(i + 1) + ": " + std::to_string(table.temperatures[i])
                         + " after " + std::to_string(table.temperatures[i - 1]) + ")");
    for (const double v : table.values)
    {
      if (positive && !(v > 0.))
        throw InputError(entry + ": must be positive (found " + std::to_string(v) + ")");
      if (non_negative && !(v >= 0.))
        throw InputError(entry + ": must not be negative (found " + std::to_string(v) + ")");
    }
    return table;
  }

  double PropertyTable::value(const double temperature) const
  {
    if (is_constant() || temperature <= temperatures.front())
      return values.front();
    if (temperature >= temperatures.back())
      return values.back();
    const auto upper = std::upper_bound(temperatures.begin(), temperatures.end(), temperature);
    const unsigned int i = upper - temperatures.begin();
    const double w = (temperature - temperatures[i - 1]) / (temperatures[i] - temperatures[i - 1]);
    return (1. - w) * values[i - 1] + w * values[i];
  }

  double PropertyTable::derivative(const double temperature) const
  {
    if (is_constant() || temperature <= temperatures.front() || temperature >= temperatures.back())
      return 0.;
    const auto upper = std::upper_bound(temperatures.begin(), temperatures.end(), temperature);
    const unsigned int i = upper - temperatures.begin();
    return (values[i] - values[i - 1]) / (temperatures[i] - temperatures[i - 1]);
  }

  double PropertyTable::min_value() const
  {
    return *std::min_element(values.begin(), values.end());
  }

  double PropertyTable::max_value() const
  {
    return *std::max_element(values.begin(), values.end());
  }
} // namespace ausroll::material
