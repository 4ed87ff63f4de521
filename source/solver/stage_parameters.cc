#include <ausroll/core/exceptions.h>
#include <ausroll/core/parse_utilities.h>
#include <ausroll/solver/loading_parameters.h>
#include <ausroll/solver/stage_parameters.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace ausroll::solver
{
  using namespace dealii;

  namespace
  {
    std::string number(const double v)
    {
      std::ostringstream s;
      s << v;
      return s.str();
    }

    /**
     * The pairs "k: text" of an override list "0: 250; 1: 20 + 5 * t" (split at ';', then at
     * the first ':' so that an expression may contain "a ? b : c"), the condition index checked
     * against the @p n_conditions of `Thermal`.
     */
    std::vector<std::pair<unsigned int, std::string>> parse_overrides(
        const std::string &text, const std::string &entry, const unsigned int n_conditions)
    {
      std::vector<std::pair<unsigned int, std::string>> out;
      for (const std::string &item : split_and_trim(text, ';'))
      {
        const auto colon = item.find(':');
        require(colon != std::string::npos,
                entry,
                "'" + abbreviate(item)
                    + "' is not 'k: value' (k the number of a Thermal/Condition k)");
        const std::vector<std::string> words = split_and_trim(item.substr(0, colon), ' ');
        const std::string              index = words.size() == 1 ? words[0] : "";
        const std::string              value = item.substr(colon + 1);
        require(!index.empty() && index.size() < 4
                    && index.find_first_not_of("0123456789") == std::string::npos,
                entry,
                "'" + abbreviate(item) + "' does not start with a condition number");
        const unsigned int k = std::stoul(index);
        require(k < n_conditions,
                entry,
                "names Thermal/Condition " + index + ", which does not exist (Thermal/Number of "
                    + "conditions = " + std::to_string(n_conditions) + ")");
        require(split_and_trim(value, ' ').size() > 0, entry, "no value after '" + index + ":'");
        for (const auto &[other, v] : out)
          require(other != k, entry, "names Thermal/Condition " + index + " twice");
        out.emplace_back(k, value);
      }
      return out;
    }
  } // namespace

  double StageParameters::start_time(const unsigned int k) const
  {
    return k == 0 ? 0. : stages[k - 1].end_time;
  }

  unsigned int StageParameters::stage_at(const double t_start) const
  {
    const double tolerance = 1e-10 * std::abs(stages.back().end_time);
    for (unsigned int k = 0; k < stages.size(); ++k)
      if (stages[k].end_time - t_start > tolerance)
        return k;
    return stages.size() - 1;
  }

  bool StageParameters::ends_stage(const double t) const
  {
    const double tolerance = 1e-10 * std::abs(stages.back().end_time);
    for (const Stage &stage : stages)
      if (std::abs(stage.end_time - t) <= tolerance)
        return true;
    return false;
  }

  double StageParameters::step_size(const unsigned int k, const double loading_step) const
  {
    return stages[k].step_size > 0. ? stages[k].step_size : loading_step;
  }

  double StageParameters::progress(const double t, const LoadingParameters &loading) const
  {
    if (stages.empty())
      return t / loading.end_time;
    const double loading_step = loading.end_time / loading.number_of_steps;
    double       done = 0., total = 0.;
    for (unsigned int k = 0; k < stages.size(); ++k)
    {
      const double length = stages[k].end_time - start_time(k), step = step_size(k, loading_step);
      total += length / step;
      done += std::clamp(t - start_time(k), 0., length) / step;
    }
    return done / total;
  }

  std::vector<double> StageParameters::sample_times(const LoadingParameters &loading,
                                                    const unsigned int       max_samples) const
  {
    std::vector<double> times{0.};
    if (stages.empty())
    {
      const unsigned int n = std::min(loading.number_of_steps, max_samples);
      for (unsigned int k = 1; k <= n; ++k)
        times.push_back(loading.end_time * k / n);
      return times;
    }
    const double loading_step = loading.end_time / loading.number_of_steps;
    double       total = 0.;
    for (unsigned int k = 0; k < stages.size(); ++k)
      total += (stages[k].end_time - start_time(k)) / step_size(k, loading_step);
    for (unsigned int k = 0; k < stages.size(); ++k)
    {
      const double length = stages[k].end_time - start_time(k);
      const double steps = std::ceil(length / step_size(k, loading_step) - 1e-9);
      // at least two samples in a stage of two or more steps, at most one per step
      const double wanted = std::max(2., std::ceil(max_samples * steps / total));
      const auto   n = static_cast<unsigned int>(std::max(1., std::min(wanted, steps)));
      for (unsigned int i = 1; i <= n; ++i)
        times.push_back(start_time(k) + length * i / n);
    }
    return times;
  }

  void StageParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Stages");
    prm.declare_entry(
        "Number of stages",
        "0",
        Patterns::Integer(0, max_stages),
        "A process chain in one run: how many of the subsections 'Stage 0', 'Stage 1', ... are "
        "used. Stage k runs from the End time of stage k - 1 (0 for stage 0) to its own End "
        "time, with its own thermal boundary values and step size; the die motions stay "
        "functions of t (Contact/Die N/Motion). Stage ends are load-step ends, the history gets "
        "a column 'stage' and the log a line where a stage begins. The End times must increase "
        "and the last must equal Loading/End time. 0: no stages (the run as without this "
        "subsection).");
    for (unsigned int i = 0; i < max_stages; ++i)
    {
      prm.enter_subsection("Stage " + std::to_string(i));
      prm.declare_entry("Name",
                        "",
                        Patterns::Anything(),
                        "Label of the stage in the log (e.g. quench, rolling, withdrawal, "
                        "cooling); empty: 'stage k'.");
      prm.declare_entry("End time",
                        "0",
                        Patterns::Double(),
                        "Time at which the stage ends (s with Thermal/Enabled = true); "
                        "greater than the End time of the stage before.");
      prm.declare_entry("Step size",
                        "0",
                        Patterns::Double(0.),
                        "Nominal (and largest) load step within the stage; the steps end on the "
                        "grid start + k Step size and at the stage's end. 0: Loading/End time / "
                        "Loading/Number of steps on the run's grid.");
      prm.declare_entry("Thermal condition values",
                        "",
                        Patterns::Anything(),
                        "Replace the Value of thermal conditions during the stage, 'k: "
                        "expression; ...' with k the number of Thermal/Condition k: the ambient "
                        "(bath) temperature of a convection, the temperature of a temperature "
                        "condition, the flux of a flux condition; expressions of x, y (z) and t, "
                        "t the run's time. Empty: the Thermal values.");
      prm.declare_entry("Heat transfer coefficients",
                        "",
                        Patterns::Anything(),
                        "Replace the Heat transfer coefficient h of convection conditions during "
                        "the stage, 'k: h; ...' (N/(mm s K)), e.g. '0: 1.5' for a quench, "
                        "'0: 0.01' for still air. Empty: the Thermal values.");
      prm.leave_subsection();
    }
    prm.leave_subsection();
  }

  void StageParameters::parse_parameters(ParameterHandler                 &prm,
                                         const LoadingParameters          &loading,
                                         const thermal::ThermalParameters &thermal)
  {
    prm.enter_subsection("Stages");
    const unsigned int n = prm.get_integer("Number of stages");
    stages.clear();
    for (unsigned int i = 0; i < n; ++i)
    {
      const std::string path = "Stages/Stage " + std::to_string(i);
      prm.enter_subsection("Stage " + std::to_string(i));
      Stage stage;
      stage.name = prm.get("Name");
      if (stage.name.empty())
        stage.name = "stage " + std::to_string(i);
      stage.end_time = prm.get_double("End time");
      const double start = i == 0 ? 0. : stages.back().end_time;
      require(stage.end_time > start,
              path + "/End time",
              "= " + prm.get("End time") + " is not after "
                  + (i == 0 ? std::string("t = 0")
                            : "the End time of Stage " + std::to_string(i - 1) + " ("
                                  + number(start) + ")")
                  + ": the stages follow each other in time and may not overlap");
      stage.step_size = prm.get_double("Step size");
      stage.thermal_conditions = thermal.conditions;
      const std::string values = prm.get("Thermal condition values");
      const std::string coefficients = prm.get("Heat transfer coefficients");
      for (const auto &[entry, text] :
           {std::pair<std::string, std::string>{"Thermal condition values", values},
            {"Heat transfer coefficients", coefficients}})
        require(text.empty() || thermal.enabled,
                path + "/" + entry,
                "is set, but Thermal/Enabled = false: a stage can only change thermal "
                "conditions of a thermal scene");
      for (const auto &[k, value] :
           parse_overrides(values, path + "/Thermal condition values", thermal.conditions.size()))
      {
        require_expression_length(value, path + "/Thermal condition values");
        stage.thermal_conditions[k].value = value;
      }
      for (const auto &[k, value] : parse_overrides(
               coefficients, path + "/Heat transfer coefficients", thermal.conditions.size()))
      {
        const std::string entry = path + "/Heat transfer coefficients";
        require(thermal.conditions[k].type == thermal::ThermalConditionType::convection,
                entry,
                "names Thermal/Condition " + std::to_string(k)
                    + ", which is not a convection (only a convection has a heat transfer "
                      "coefficient)");
        const double h = parse_double(value, entry);
        require(h > 0.,
                entry,
                "the coefficient of condition " + std::to_string(k) + " must be positive, found "
                    + value);
        stage.thermal_conditions[k].heat_transfer_coefficient = h;
      }
      stages.push_back(stage);
      prm.leave_subsection();
    }
    // Stage subsections beyond Number of stages would silently do nothing.
    for (unsigned int i = n; i < max_stages; ++i)
    {
      prm.enter_subsection("Stage " + std::to_string(i));
      for (const auto &[entry, unset] : {std::pair<std::string, std::string>{"Name", ""},
                                         {"End time", "0"},
                                         {"Step size", "0"},
                                         {"Thermal condition values", ""},
                                         {"Heat transfer coefficients", ""}})
        require(prm.get(entry) == unset,
                "Stages/Stage " + std::to_string(i) + "/" + entry,
                "is set, but Stages/Number of stages = " + std::to_string(n));
      prm.leave_subsection();
    }
    prm.leave_subsection();
    if (!stages.empty())
    {
      const double last = stages.back().end_time;
      require(std::abs(last - loading.end_time) <= 1e-12 * std::abs(loading.end_time),
              "Stages/Stage " + std::to_string(n - 1) + "/End time",
              "= " + number(last) + (last > loading.end_time ? " is after" : " is before")
                  + " Loading/End time = " + number(loading.end_time)
                  + ": the last stage ends the run (set both to the same time)");
    }
  }
} // namespace ausroll::solver
