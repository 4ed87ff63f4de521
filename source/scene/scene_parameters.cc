#include <ausroll/core/exceptions.h>
#include <ausroll/scene/scene_parameters.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <vector>

namespace ausroll::scene
{
  using namespace dealii;

  void SceneParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Scene name",
                      "unnamed scene",
                      Patterns::Anything(),
                      "Label of the run, printed in the log.");
    geometry::GeometryParameters::declare_parameters(prm);
    mechanics::ModelParameters::declare_parameters(prm);
    material::MaterialParameters::declare_parameters(prm);
    mechanics::BoundaryConditionParameters::declare_parameters(prm);
    contact::ContactParameters::declare_parameters(prm);
    adaptivity::AdaptivityParameters::declare_parameters(prm);
    io::CheckpointParameters::declare_parameters(prm);
    solver::LoadingParameters::declare_parameters(prm);
    solver::SolverParameters::declare_parameters(prm);
    io::OutputParameters::declare_parameters(prm);
    io::PostprocessParameters::declare_parameters(prm);
  }

  void SceneParameters::parse_parameters(ParameterHandler &prm, const std::string &input_directory)
  {
    name = prm.get("Scene name");
    geometry.parse_parameters(prm, input_directory);
    model.parse_parameters(prm);
    material.parse_parameters(prm);
    boundary_conditions.parse_parameters(prm);
    contact.parse_parameters(prm, input_directory);
    // k of the shear friction laws: the workpiece's initial yield stress (forming practice)
    contact.set_workpiece_yield_stress(
        material.yield_criterion == material::YieldCriterion::none ? 0. : material.yield_stress);
    adaptivity.parse_parameters(prm);
    checkpoint.parse_parameters(prm);
    loading.parse_parameters(prm);
    solver.parse_parameters(prm);
    output.parse_parameters(prm);
    postprocess.parse_parameters(prm);
  }

  namespace
  {
    /** The "Additional information" of a deal.II exception on one line, without boilerplate. */
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

    /** The subsection path ("Material", "Geometry/Rectangle") in effect at line @p line_number. */
    std::string subsection_at_line(const std::string &filename, const unsigned int line_number)
    {
      std::ifstream            in(filename);
      std::vector<std::string> stack;
      std::string              line;
      for (unsigned int n = 1; n < line_number && std::getline(in, line); ++n)
      {
        line = line.substr(0, line.find('#'));
        std::istringstream words(line);
        std::string        keyword;
        words >> keyword;
        if (keyword == "subsection")
        {
          std::string name;
          std::getline(words, name);
          const auto first = name.find_first_not_of(" \t");
          const auto last = name.find_last_not_of(" \t");
          stack.push_back(first == std::string::npos ? "" : name.substr(first, last - first + 1));
        }
        else if (keyword == "end" && !stack.empty())
          stack.pop_back();
      }
      std::string path;
      for (const std::string &s : stack)
        path += (path.empty() ? "" : "/") + s;
      return path;
    }

    /** Turn a ParameterHandler parse error into "file:line: [in subsection 'X':] message". */
    std::string parse_error_message(const std::string &filename, const ExceptionBase &e)
    {
      std::string text = user_message(e);
      // deal.II starts the text with "Line <N> of file <name>:"; keep N, name the subsection.
      const auto open = text.find("Line <");
      const auto close = text.find('>', open);
      if (open == std::string::npos || close == std::string::npos)
        return filename + ": " + text;
      const std::string number = text.substr(open + 6, close - open - 6);
      const auto        colon = text.find(">:", close + 1);
      if (colon != std::string::npos)
        text = text.substr(colon + 2);
      while (!text.empty() && text.front() == ' ')
        text.erase(text.begin());
      const std::string path = subsection_at_line(filename, std::stoi(number));
      return filename + ":" + number + ": " + (path.empty() ? "" : "in subsection '" + path + "': ")
             + text;
    }
  } // namespace

  namespace
  {
    /**
     * The text of @p filename with every relative `include` path that names a file next to
     * @p filename replaced by that path, so that `include base.prm` works from any working
     * directory (ParameterHandler resolves includes relative to the working directory). Paths
     * not found there are left alone. Lines keep their numbers.
     */
    std::string resolve_includes(std::istream &in, const std::string &filename)
    {
      const std::filesystem::path directory = std::filesystem::path(filename).parent_path();
      const std::regex            include_line(R"(^(\s*include\s+)(\S(.*\S)?)\s*$)");
      std::ostringstream          out;
      std::string                 line;
      std::smatch                 match;
      while (std::getline(in, line))
      {
        if (std::regex_match(line, match, include_line))
        {
          const std::filesystem::path path(match[2].str());
          if (path.is_relative() && std::filesystem::exists(directory / path))
            line = match[1].str() + (directory / path).string();
        }
        out << line << '\n';
      }
      return out.str();
    }
  } // namespace

  SceneParameters read_parameter_file(const std::string &filename)
  {
    std::ifstream file(filename);
    if (!file)
      throw InputError("cannot open parameter file '" + filename + "'");
    std::istringstream in(resolve_includes(file, filename));

    ParameterHandler prm;
    SceneParameters::declare_parameters(prm);
    try
    {
      prm.parse_input(in, filename, "", /*skip_undefined=*/false);
    }
    catch (const ExceptionBase &e)
    {
      throw InputError(parse_error_message(filename, e));
    }

    const auto      slash = filename.find_last_of('/');
    std::string     directory = slash == std::string::npos ? "" : filename.substr(0, slash + 1);
    SceneParameters parameters;
    try
    {
      parameters.parse_parameters(prm, directory);
    }
    catch (const ExceptionBase &e)
    {
      throw InputError(filename + ": " + user_message(e));
    }
    return parameters;
  }
} // namespace ausroll::scene
