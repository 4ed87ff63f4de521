#include <ausroll/core/exceptions.h>
#include <ausroll/core/parse_utilities.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace ausroll
{
  std::vector<std::string> split_and_trim(const std::string &text, const char delimiter)
  {
    std::vector<std::string> pieces;
    std::stringstream        stream(text);
    std::string              piece;
    while (std::getline(stream, piece, delimiter))
    {
      const auto first = piece.find_first_not_of(" \t\n\r");
      if (first == std::string::npos)
        continue;
      const auto last = piece.find_last_not_of(" \t\n\r");
      pieces.push_back(piece.substr(first, last - first + 1));
    }
    return pieces;
  }

  std::string abbreviate(const std::string &text)
  {
    if (text.size() <= 80)
      return text;
    return text.substr(0, 60) + " ... (" + std::to_string(text.size()) + " characters)";
  }

  void require_expression_length(const std::string &expression, const std::string &entry)
  {
    constexpr std::size_t max_length = 20000; // muparser's MaxLenExpression
    if (expression.size() >= max_length)
      throw InputError(entry + ": expression too long (" + std::to_string(expression.size())
                       + " characters; the expression parser accepts fewer than "
                       + std::to_string(max_length) + "): '" + abbreviate(expression) + "'");
  }

  double parse_double(const std::string &text, const std::string &entry)
  {
    const char  *begin = text.c_str();
    char        *end = nullptr;
    const double value = std::strtod(begin, &end);
    if (end == begin || std::string(end).find_first_not_of(" \t") != std::string::npos)
      throw InputError(entry + ": '" + abbreviate(text) + "' is not a number");
    if (!std::isfinite(value) || std::abs(value) > 1e30)
      throw InputError(entry + ": '" + abbreviate(text)
                       + "' is out of range (magnitude above 1e30, inf or nan)");
    return value;
  }

  std::vector<double> parse_double_list(const std::string &text, const std::string &entry)
  {
    std::vector<double> values;
    for (const std::string &piece : split_and_trim(text, ','))
      values.push_back(parse_double(piece, entry));
    return values;
  }

  std::vector<unsigned int> parse_unsigned_list(const std::string &text, const std::string &entry)
  {
    std::vector<unsigned int> values;
    for (const double v : parse_double_list(text, entry))
    {
      if (v < 0 || v != static_cast<double>(static_cast<unsigned int>(v)))
        throw InputError(entry + ": '" + text + "' must be a list of non-negative integers");
      values.push_back(static_cast<unsigned int>(v));
    }
    return values;
  }

  void require_label(const std::string &name, const std::string &entry)
  {
    const bool allowed = !name.empty() && name.size() <= 64 && name != "." && name != ".."
                         && std::all_of(name.begin(),
                                        name.end(),
                                        [](const char c) {
                                          return std::isalnum(static_cast<unsigned char>(c))
                                                 || c == '_' || c == '-' || c == '.';
                                        });
    if (!allowed)
      throw InputError(entry + ": '" + abbreviate(name)
                       + "' must be a single word of at most 64 letters, digits, '_', '-' or '.' "
                         "(not '.' or '..'): it names history.csv columns and output files");
  }

  void require_unique_labels(const std::vector<std::string> &names, const std::string &entry)
  {
    for (std::size_t i = 0; i < names.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (names[i] == names[j])
          throw InputError(entry + ": the name '" + names[i]
                           + "' is used twice; each needs a name of its own (it names "
                             "history.csv columns and output files)");
  }

  template <int dim>
  dealii::Point<dim> parse_point(const std::string &text, const std::string &entry)
  {
    const std::vector<double> values = parse_double_list(text, entry);
    if (values.size() != dim)
      throw InputError(entry + ": '" + text + "' must have " + std::to_string(dim)
                       + " coordinates");
    dealii::Point<dim> p;
    for (unsigned int d = 0; d < dim; ++d)
      p[d] = values[d];
    return p;
  }

  template <int dim>
  std::vector<std::pair<std::string, dealii::Point<dim>>>
  parse_named_points(const std::string &text, const std::string &entry)
  {
    std::vector<std::pair<std::string, dealii::Point<dim>>> points;
    for (const std::string &item : split_and_trim(text, ';'))
    {
      const auto colon = item.find(':');
      if (colon == std::string::npos || colon == 0)
        throw InputError(entry + ": '" + item + "' must read 'name: x, y'");
      // the whole text before the colon, trimmed ("a b" is refused, not cut to "a")
      const std::vector<std::string> before = split_and_trim(item.substr(0, colon), '\n');
      const std::string              name = before.empty() ? std::string() : before.front();
      require_label(name, entry);
      points.emplace_back(name, parse_point<dim>(item.substr(colon + 1), entry));
    }
    std::vector<std::string> names;
    for (const auto &p : points)
      names.push_back(p.first);
    require_unique_labels(names, entry);
    return points;
  }

  template dealii::Point<2> parse_point<2>(const std::string &, const std::string &);
  template dealii::Point<3> parse_point<3>(const std::string &, const std::string &);
  template std::vector<std::pair<std::string, dealii::Point<2>>>
  parse_named_points<2>(const std::string &, const std::string &);
  template std::vector<std::pair<std::string, dealii::Point<3>>>
  parse_named_points<3>(const std::string &, const std::string &);
} // namespace ausroll
