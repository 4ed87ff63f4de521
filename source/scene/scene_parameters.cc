#include <ausroll/core/exceptions.h>
#include <ausroll/core/parameter_file.h>
#include <ausroll/scene/scene_parameters.h>

#include <map>
#include <sstream>
#include <string>
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
    thermal::ThermalParameters::declare_parameters(prm);
    CouplingParameters::declare_parameters(prm);
    material::PhaseParameters::declare_parameters(prm);
    solver::StageParameters::declare_parameters(prm);
  }

  void SceneParameters::parse_parameters(ParameterHandler &prm, const std::string &input_directory)
  {
    name = prm.get("Scene name");
    geometry.parse_parameters(prm, input_directory);
    model.parse_parameters(prm);
    material.parse_parameters(prm, input_directory);
    boundary_conditions.parse_parameters(prm);
    contact.parse_parameters(prm, input_directory);
    adaptivity.parse_parameters(prm);
    checkpoint.parse_parameters(prm);
    loading.parse_parameters(prm);
    solver.parse_parameters(prm);
    output.parse_parameters(prm);
    postprocess.parse_parameters(prm);
    thermal.parse_parameters(prm, input_directory);
    coupling.parse_parameters(prm, thermal.enabled);
    phases.parse_parameters(prm, thermal.enabled, input_directory);
    if (phases.enabled) // the heat equation's source of the transformation
    {
      thermal.latent_heat_martensite = phases.latent_heat;
      thermal.latent_heat_bainite = phases.bainite_latent_heat;
    }
    stages.parse_parameters(prm, loading, thermal);
    require(adaptivity.case_level < 0 || phases.enabled,
            "Adaptivity/Case level",
            "refines the carbon case: set Phases/Enabled = true (and a Carbon content)");
    const std::string table_entry = material.first_temperature_dependent_entry();
    require(table_entry.empty() || thermal.enabled,
            table_entry,
            "a table in temperature needs the temperature field: set Thermal/Enabled = true (or "
            "give a single value)");
  }

  SceneParameters read_parameter_file(const std::string                    &filename,
                                      const std::vector<ParameterOverride> &overrides)
  {
    const ParameterText text = expand_parameter_file(filename);
    ParameterHandler    prm;
    SceneParameters::declare_parameters(prm);
    std::map<std::string, std::string> moved = contact::ContactParameters::moved_entries();
    moved.merge(solver::LoadingParameters::moved_entries());
    parse_parameter_text(prm, text, overrides, moved);
    const std::map<std::string, std::string> entries = flatten_parameters(prm);
    check_number_magnitudes(entries);

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
    parameters.entries = entries;
    std::ostringstream printed;
    prm.print_parameters(printed, ParameterHandler::PRM);
    parameters.effective_parameters = printed.str();
    return parameters;
  }
} // namespace ausroll::scene
