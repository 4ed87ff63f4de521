/**
 * @file scene_parameters.h
 * All parameters of a scene (.prm file), one struct per subsection.
 */
#pragma once

#include <ausroll/adaptivity/adaptivity_parameters.h>
#include <ausroll/contact/contact_parameters.h>
#include <ausroll/core/parameter_file.h>
#include <ausroll/geometry/geometry_parameters.h>
#include <ausroll/io/checkpoint.h>
#include <ausroll/io/output_parameters.h>
#include <ausroll/material/material_parameters.h>
#include <ausroll/material/phase_transformation_model.h>
#include <ausroll/mechanics/boundary_conditions.h>
#include <ausroll/mechanics/model_parameters.h>
#include <ausroll/scene/coupling_parameters.h>
#include <ausroll/solver/loading_parameters.h>
#include <ausroll/solver/solver_parameters.h>
#include <ausroll/solver/stage_parameters.h>
#include <ausroll/thermal/thermal_parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <map>
#include <string>
#include <vector>

namespace ausroll::scene
{
  /**
   * The complete input of a run. Top-level entry: `Scene name` (a label printed in the log).
   */
  struct SceneParameters
  {
    std::string                            name = "unnamed scene"; ///< `Scene name`
    geometry::GeometryParameters           geometry;               ///< `Geometry`
    mechanics::ModelParameters             model;                  ///< `Model`
    material::MaterialParameters           material;               ///< `Material`
    mechanics::BoundaryConditionParameters boundary_conditions;    ///< `Boundary conditions`
    contact::ContactParameters             contact;                ///< `Contact`
    adaptivity::AdaptivityParameters       adaptivity;             ///< `Adaptivity`
    io::CheckpointParameters               checkpoint;             ///< `Checkpoint`
    solver::LoadingParameters              loading;                ///< `Loading`
    solver::SolverParameters               solver;                 ///< `Solver`
    io::OutputParameters                   output;                 ///< `Output`
    io::PostprocessParameters              postprocess;            ///< `Postprocess`
    thermal::ThermalParameters             thermal;                ///< `Thermal`
    CouplingParameters                     coupling;               ///< `Coupling`
    material::PhaseParameters              phases;                 ///< `Phases`
    solver::StageParameters                stages;                 ///< `Stages`
    /** Every entry "Section/Entry" -> value as parsed (stored in checkpoints, compared on resume).
     */
    std::map<std::string, std::string> entries;
    /** Every entry as parsed (includes expanded, overrides applied) in deal.II's PRM format with
        documentation; an entry that differs from its default ends in `# default: ...`. Written
        to `<Output/Directory>/parameters.prm`, printed by `--print-parameters FILE.prm`. */
    std::string effective_parameters;

    /** Declare every entry of every subsection. */
    static void declare_parameters(dealii::ParameterHandler &prm);

    /** Read all subsections (files named in the input are resolved relative to @p input_directory).
     */
    void parse_parameters(dealii::ParameterHandler &prm, const std::string &input_directory);
  };

  /**
   * Read @p filename into a SceneParameters. Syntax errors, unknown entries and values that do not
   * match their pattern become an InputError that names the file, line and entry.
   */
  SceneParameters read_parameter_file(const std::string                    &filename,
                                      const std::vector<ParameterOverride> &overrides = {});
} // namespace ausroll::scene
