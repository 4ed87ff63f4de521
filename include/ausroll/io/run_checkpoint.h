/**
 * @file run_checkpoint.h
 * What a checkpoint of a run holds and how it is written and read back: the mesh (saved by the
 * p4est triangulation), the converged solution and the one before it, the material points, and
 * the scalars of RunState in `metadata.txt` (io/checkpoint.h: directory and metadata format).
 *
 * Resuming, in this order: load_checkpoint_mesh() (after the coarse mesh was made), the system's
 * setup and material points, load_checkpoint_vectors(), then read_run_state() for the rest.
 */
#pragma once

#include <ausroll/adaptivity/material_point_transfer.h>
#include <ausroll/mechanics/mechanical_system.h>
#include <ausroll/thermal/thermal_system.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace ausroll::io
{
  /** The run's scalars a checkpoint keeps besides mesh, vectors and material points. */
  struct RunState
  {
    double              time = 0.;             ///< pseudo-time of the converged state
    unsigned int        step = 0;              ///< converged steps
    double              step_size = 0.;        ///< step size to continue with
    double              last_step_size = 0.;   ///< size of the last step (predictor; 0: none)
    unsigned int        output_counter = 0;    ///< outputs written
    int                 last_output_step = -1; ///< step of the last output
    double              largest_reference_force = 0.;        ///< largest force level so far
    std::vector<double> contact;                             ///< ContactOperator::pack_state()
    std::vector<std::pair<double, std::string>> vtu_records; ///< (time, file) of the VTU outputs
  };

  /**
   * Write a checkpoint of the converged state of @p system (solution, previous_start, mesh and,
   * through @p points, the material points) with @p state and the run's parameter @p entries into
   * `<output_directory>/checkpoint/` (atomically, CheckpointDirectory). Collective.
   */
  template <int dim>
  void write_checkpoint(mechanics::MechanicalSystem<dim>         &system,
                        adaptivity::MaterialPointTransfer<dim>   &points,
                        const RunState                           &state,
                        const std::map<std::string, std::string> &entries,
                        const std::string                        &output_directory,
                        thermal::ThermalSystem<dim>              *thermal = nullptr);

  /**
   * Resume: load the refined, partitioned mesh of the latest checkpoint of @p output_directory
   * into @p system's triangulation (which holds the coarse mesh), after comparing the parameter
   * @p entries of this run with the checkpoint's (compare_resume_parameters: InputError for a
   * changed mesh entry, a warning on std::cerr for others). Returns the checkpoint directory.
   */
  template <int dim>
  std::string load_checkpoint_mesh(mechanics::MechanicalSystem<dim>         &system,
                                   const std::map<std::string, std::string> &entries,
                                   const std::string                        &output_directory);

  /**
   * Resume, after the system's setup on the loaded mesh: read solution (= step_start) and, if the
   * checkpoint has it, previous_start, and the material points (through @p points) from
   * @p directory.
   */
  template <int dim>
  void load_checkpoint_vectors(mechanics::MechanicalSystem<dim>       &system,
                               adaptivity::MaterialPointTransfer<dim> &points,
                               const std::string                      &directory,
                               thermal::ThermalSystem<dim>            *thermal = nullptr);

  /** The RunState stored in the checkpoint @p directory. */
  RunState read_run_state(const std::string &directory);
} // namespace ausroll::io
