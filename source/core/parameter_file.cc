#include <ausroll/core/exceptions.h>
#include <ausroll/core/input_file.h>
#include <ausroll/core/parameter_file.h>
#include <ausroll/core/parse_utilities.h>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <regex>
#include <sstream>

namespace ausroll
{
  using namespace dealii;
  namespace fs = std::filesystem;

  namespace
  {
    constexpr unsigned int max_include_depth = 32;

    std::string trim(const std::string &s)
    {
      const auto first = s.find_first_not_of(" \t\r\n");
      if (first == std::string::npos)
        return "";
      return s.substr(first, s.find_last_not_of(" \t\r\n") - first + 1);
    }

    std::string chain_text(const std::vector<std::string> &chain)
    {
      std::string text;
      for (const std::string &f : chain)
        text += (text.empty() ? "" : " -> ") + f;
      return text;
    }

    /**
     * Refuse @p path unless it is a readable regular file of at most
     * file_size_limit::parameter_file bytes (a FIFO would block, /dev/zero would fill the
     * memory); @p where prefixes the message.
     */
    void require_regular_file(const fs::path &path, const std::string &where)
    {
      const std::string problem
          = input_file_problem(path.string(), file_size_limit::parameter_file);
      if (problem.rfind("is a directory", 0) == 0)
        throw InputError(where + "'" + path.string() + "' is a directory, not a parameter file");
      if (!problem.empty())
        throw InputError(where + "cannot open parameter file '" + path.string() + "' (" + problem
                         + ")");
    }

    void expand(const fs::path           &path,
                const std::string        &name,
                std::vector<std::string> &chain,
                std::vector<std::string> &canonical_chain,
                ParameterText            &out)
    {
      std::ifstream in
          = open_input_file(path.string(), "parameter file", file_size_limit::parameter_file);
      const std::regex include_line(R"(^\s*include\s+(\S(.*\S)?)\s*$)");
      std::string      line;
      std::smatch      match;
      unsigned int     number = 0;
      while (std::getline(in, line))
      {
        ++number;
        // A UTF-8 byte-order mark (some Windows editors write one) is not part of the text.
        if (number == 1 && line.compare(0, 3, "\xEF\xBB\xBF") == 0)
          line.erase(0, 3);
        if (!line.empty() && line.back() == '\r')
          line.pop_back();
        const std::string where = name + ":" + std::to_string(number) + ": ";
        if (std::regex_match(line, match, include_line))
        {
          const fs::path  target(match[1].str());
          fs::path        resolved = target;
          std::error_code ec;
          if (target.is_relative()
              && fs::symlink_status(path.parent_path() / target, ec).type()
                     != fs::file_type::not_found)
            resolved = path.parent_path() / target;
          require_regular_file(resolved, where + "include: ");
          const std::string canonical = fs::weakly_canonical(resolved).string();
          chain.push_back(resolved.string());
          for (const std::string &c : canonical_chain)
            if (c == canonical)
              throw InputError(where + "include '" + target.string()
                               + "' includes a file that is already being read: "
                               + chain_text(chain));
          if (chain.size() > max_include_depth)
            throw InputError(where + "more than " + std::to_string(max_include_depth)
                             + " nested includes: " + chain_text(chain));
          canonical_chain.push_back(canonical);
          expand(resolved, resolved.string(), chain, canonical_chain, out);
          chain.pop_back();
          canonical_chain.pop_back();
          continue;
        }
        out.text += line + '\n';
        out.origin.push_back({name, number});
      }
    }

    /** The subsection path in effect before line @p line (1-based) of @p text. */
    std::string subsection_at_line(const std::string &text, const unsigned int line)
    {
      std::istringstream       in(text);
      std::vector<std::string> stack;
      std::string              l;
      for (unsigned int n = 1; n < line && std::getline(in, l); ++n)
      {
        l = l.substr(0, l.find('#'));
        std::istringstream words(l);
        std::string        keyword;
        words >> keyword;
        if (keyword == "subsection")
        {
          std::string name;
          std::getline(words, name);
          stack.push_back(trim(name));
        }
        else if (keyword == "end" && !stack.empty())
          stack.pop_back();
      }
      std::string path;
      for (const std::string &s : stack)
        path += (path.empty() ? "" : "/") + s;
      return path;
    }

    /**
     * "file:line: [in subsection 'X':] message" from a deal.II parse error, whose text starts
     * with "Line <N> of file <name>:" (N counts lines of the expanded @p text).
     */
    std::string parse_error_message(const ParameterText                      &text,
                                    const ExceptionBase                      &e,
                                    const std::map<std::string, std::string> &moved_entries)
    {
      std::string message = user_message(e);
      const auto  open = message.find("Line <");
      const auto  close = message.find('>', open);
      if (open == std::string::npos || close == std::string::npos)
        return (text.origin.empty() ? std::string() : text.origin.front().file + ": ") + message;
      const unsigned int n = std::atoi(message.substr(open + 6, close - open - 6).c_str());
      const auto         colon = message.find(">:", close + 1);
      if (colon != std::string::npos)
        message = trim(message.substr(colon + 2));
      const std::string path = subsection_at_line(text.text, n);
      // an entry that moved: say where it is now
      const std::string unknown = "No entry with name <";
      if (message.rfind(unknown, 0) == 0 && message.find('>') != std::string::npos)
      {
        const std::string entry
            = message.substr(unknown.size(), message.find('>') - unknown.size());
        const auto moved = moved_entries.find((path.empty() ? "" : path + "/") + entry);
        if (moved != moved_entries.end())
          message = "`" + moved->first + "` moved to " + moved->second;
      }
      const LineOrigin where = n >= 1 && n <= text.origin.size() ? text.origin[n - 1]
                               : text.origin.empty()             ? LineOrigin{"input", 0}
                                                                 : text.origin.back();
      return where.file + (where.line > 0 ? ":" + std::to_string(where.line) : std::string()) + ": "
             + (path.empty() ? "" : "in subsection '" + path + "': ") + message;
    }
  } // namespace

  std::string user_message(const ExceptionBase &e)
  {
    std::ostringstream out;
    e.print_info(out);
    std::string        text, word;
    std::istringstream words(out.str());
    while (words >> word)
      text += (text.empty() ? "" : " ") + word;
    return text.empty() ? std::string(e.get_exc_name()) : text;
  }

  ParameterText expand_parameter_file(const std::string &filename)
  {
    require_regular_file(filename, "");
    ParameterText            text;
    std::vector<std::string> chain{filename};
    std::vector<std::string> canonical_chain{fs::weakly_canonical(filename).string()};
    expand(filename, filename, chain, canonical_chain, text);

    bool has_content = false;
    for (std::istringstream lines(text.text); !has_content;)
    {
      std::string line;
      if (!std::getline(lines, line))
        break;
      has_content = !trim(line.substr(0, line.find('#'))).empty();
    }
    if (!has_content)
      throw InputError(filename
                       + ": no entries (the file is empty or holds only comments); "
                         "see 'ausroll --print-parameters' for what a scene sets");
    return text;
  }

  ParameterOverride parse_override(const std::string &argument)
  {
    const auto equal = argument.find('=');
    if (equal == std::string::npos)
      throw UsageError("--set '" + argument + "': expected \"Section/Entry=value\"");
    // One override is one line of the file: a line break would start other entries (or
    // subsections) that the command line does not show.
    for (const char c : argument)
      if (c == '\n' || c == '\r' || c == '\0' || c == '\v' || c == '\f')
      {
        std::string shown;
        for (const char d : argument)
          shown += d == '\n'   ? std::string("\\n")
                   : d == '\r' ? std::string("\\r")
                               : std::string(1, d);
        throw UsageError("--set '" + abbreviate(shown)
                         + "': contains a line break or another control character; one --set "
                           "sets one entry (repeat --set for more)");
      }
    ParameterOverride o;
    o.argument = argument;
    o.value = trim(argument.substr(equal + 1));
    std::vector<std::string> path = split_and_trim(argument.substr(0, equal), '/');
    if (path.size() < 1 || trim(argument.substr(0, equal)).empty())
      throw UsageError("--set '" + argument + "': expected \"Section/Entry=value\"");
    o.entry = path.back();
    path.pop_back();
    o.subsections = path;
    return o;
  }

  void parse_parameter_text(ParameterHandler                         &prm,
                            const ParameterText                      &text,
                            const std::vector<ParameterOverride>     &overrides,
                            const std::map<std::string, std::string> &moved_entries)
  {
    try
    {
      std::istringstream in(text.text);
      prm.parse_input(in,
                      text.origin.empty() ? std::string("input") : text.origin.front().file,
                      "",
                      /*skip_undefined=*/false);
    }
    catch (const ExceptionBase &e)
    {
      throw InputError(parse_error_message(text, e, moved_entries));
    }
    for (const ParameterOverride &o : overrides)
    {
      ParameterText line;
      for (const std::string &s : o.subsections)
      {
        line.text += "subsection " + s + "\n";
        line.origin.push_back({"--set '" + o.argument + "'", 0});
      }
      line.text += "set " + o.entry + " = " + o.value + "\n";
      line.origin.push_back({"--set '" + o.argument + "'", 0});
      for (std::size_t k = 0; k < o.subsections.size(); ++k)
      {
        line.text += "end\n";
        line.origin.push_back({"--set '" + o.argument + "'", 0});
      }
      try
      {
        std::istringstream in(line.text);
        prm.parse_input(in, "--set", "", /*skip_undefined=*/false);
      }
      catch (const ExceptionBase &e)
      {
        throw InputError(parse_error_message(line, e, moved_entries));
      }
    }
  }

  std::map<std::string, std::string> flatten_parameters(const ParameterHandler &prm)
  {
    std::ostringstream out;
    prm.print_parameters(out, ParameterHandler::ShortPRM);
    std::map<std::string, std::string> entries;
    std::vector<std::string>           stack;
    std::istringstream                 in(out.str());
    std::string                        line;
    while (std::getline(in, line))
    {
      line = trim(line);
      if (line.rfind("subsection ", 0) == 0)
        stack.push_back(trim(line.substr(11)));
      else if (line == "end" && !stack.empty())
        stack.pop_back();
      else if (line.rfind("set ", 0) == 0)
      {
        const auto  equal = line.find('=');
        std::string path;
        for (const std::string &s : stack)
          path += s + "/";
        entries[path + trim(line.substr(4, equal - 4))]
            = equal == std::string::npos ? "" : trim(line.substr(equal + 1));
      }
    }
    return entries;
  }

  void check_number_magnitudes(const std::map<std::string, std::string> &entries)
  {
    const auto word_char
        = [](const char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
    for (const auto &[entry, value] : entries)
    {
      // labels and paths are not numbers
      const std::string name = entry.substr(entry.find_last_of('/') + 1);
      if (name == "Name" || name == "Scene name" || name == "Directory"
          || name.find("file") != std::string::npos)
        continue;
      for (std::size_t i = 0; i < value.size(); ++i)
      {
        if (i > 0 && (word_char(value[i - 1]) || value[i - 1] == '.'))
          continue;
        const char  c = value[i];
        std::size_t length = 0;
        double      x = 0.;
        if (std::isdigit(static_cast<unsigned char>(c)) || c == '.')
        {
          char *end = nullptr;
          x = std::strtod(value.c_str() + i, &end);
          length = end - (value.c_str() + i);
        }
        else if (std::isalpha(static_cast<unsigned char>(c)))
        {
          std::size_t j = i;
          while (j < value.size() && word_char(value[j]))
            ++j;
          std::string word = value.substr(i, j - i);
          for (char &w : word)
            w = std::tolower(static_cast<unsigned char>(w));
          if (word == "inf" || word == "infinity" || word == "nan")
          {
            x = std::numeric_limits<double>::infinity();
            length = j - i;
          }
          else
            i = j - 1;
        }
        if (length == 0)
          continue;
        if (!std::isfinite(x) || std::abs(x) > 1e30)
          throw InputError(entry + ": '" + value.substr(i, length)
                           + (length == value.size() ? std::string() : "' in '" + abbreviate(value))
                           + "' is out of range: no entry takes magnitudes above 1e30, inf or "
                             "nan (they overflow in the computation)");
        i += length - 1;
      }
    }
  }
} // namespace ausroll
