/**
 * @file mesh_adaptation.cc
 * The members of Scene that follow a change of the mesh or of the DoFs (as ASPECT keeps
 * Simulator's mesh refinement apart from its core): the parts set up on the DoFs, and the
 * adaptation of the mesh (marking by the registered refinement indicators, the transfer of
 * displacement, material points, temperature and contact statuses, the re-equilibration), and
 * the check of the mesh's distortion after every step.
 */
#include <ausroll/adaptivity/refinement_indicators.h>
#include <ausroll/core/exceptions.h>
#include <ausroll/scene/scene.h>

#include <algorithm>
#include <tuple>

namespace ausroll::scene
{
  using namespace dealii;

  template <int dim>
  void Scene<dim>::setup_dof_dependents()
  {
    linear_solver.set_rigid_body_modes(system.dof_handler, system.mapping);
    contact.setup(
        system.dof_handler,
        system.mapping,
        [this](const Point<dim> &x) { return kinematics.volume_factor(x); },
        system.min_cell_diameter);
    if (contact.active())
      non_candidate_penetration.setup(system.mapping, system.dof_handler);
  }

  template <int dim>
  bool Scene<dim>::adapt_mesh(const double next_time)
  {
    const adaptivity::AdaptivityParameters &p = parameters.adaptivity;
    unsigned int                            n_refined = 0, n_coarsened = 0;
    {
      TimerOutput::Scope                 scope(*timer, "adaptivity");
      const adaptivity::DieDistance<dim> die_distance
          = contact.active() ? adaptivity::DieDistance<dim>(
                [this, next_time](const Point<dim> &x) {
                  return std::min(contact.distance_to_dies(x, time),
                                  contact.distance_to_dies(x, next_time));
                })
                             : adaptivity::DieDistance<dim>();
      if (!adaptivity::mark_cells(p,
                                  system.triangulation,
                                  system.mapping,
                                  system.dof_handler,
                                  system.solution_ghosted,
                                  system.material_points,
                                  die_distance))
        return false;

      // Carry displacement, material points and contact statuses to the new mesh.
      const std::vector<double> contact_state = contact.pack_state();
      linear_solver.matrix_pattern_changed();
      // (the counts for the log: cells split and cells merged into their parents)
      std::tie(n_refined, n_coarsened) = system.execute_refinement(
          [this]()
          {
            point_transfer->prepare();
            if (thermal)
              thermal->prepare_refinement();
          },
          [this]()
          {
            setup_dof_dependents();
            point_transfer->unpack();
            if (thermal)
            {
              thermal->setup();
              thermal->finish_refinement();
            }
          });
      system.rebase_material_points(*assembler, *model);
      contact.unpack_state(contact_state);
      setup_postprocessing();
    }
    log << "  mesh adapted: " << system.triangulation.n_global_active_cells() << " cells, "
        << system.dof_handler.n_dofs() << " DoFs (" << n_refined << " cells refined, "
        << n_coarsened << " coarsened)" << std::endl;

    // Before the first step (initial refinement cycles, t = 0) nothing has been solved yet: the
    // interpolated state is the undeformed one and Newton would only chase round-off.
    if (p.reequilibrate && time > 0.)
    {
      // Equilibrium on the new mesh at the same time (no load change). In a thermal scene the
      // heat solve of the last step has already written the next step's temperature into the
      // points: the re-equilibration evaluates them at the temperature of their state, and the
      // next step carries its own thermal and transformation increment.
      if (thermal)
      {
        thermal->hold_point_temperatures(system.material_points);
        ++system.assembly_cache.state;
      }
      const solver::NewtonResult result = newton.solve(*equilibrium, newton_log);
      if (result.converged)
        commit_step(false); // the predictor's u_n-1 stays the last step's converged state
      else
      {
        // as with Re-equilibrate = false: the next step starts from the transferred state and
        // its Newton (with its cutbacks) removes the imbalance together with the step's load
        system.restore_step_start();
        contact.update_geometry(system.solution_ghosted, false);
        log << "  warning: re-equilibration after mesh adaptation at t = " << time << " failed ("
            << result.reason << "); the next step starts from the transferred state" << std::endl;
      }
      if (thermal)
      {
        thermal->release_point_temperatures(system.material_points);
        ++system.assembly_cache.state;
      }
    }
    return true;
  }

  template <int dim>
  void Scene<dim>::check_distortion()
  {
    if (!distortion.check(system.mapping,
                          system.dof_handler,
                          assembler->quadrature(),
                          kinematics,
                          system.solution_ghosted,
                          step_number,
                          time,
                          newton_log))
      return;
    log << "  warning: " << distortion.warning() << std::endl;
    if (parameters.loading.stop_at_distortion)
    {
      write_output();
      throw RunFailure(distortion.warning() + " (Loading/Stop at distorted mesh = true). The "
                       + "state of step " + std::to_string(step_number) + " is in "
                       + parameters.output.directory + "/");
    }
  }

  template void Scene<2>::setup_dof_dependents();
  template bool Scene<2>::adapt_mesh(const double);
  template void Scene<2>::check_distortion();
  template void Scene<3>::setup_dof_dependents();
  template bool Scene<3>::adapt_mesh(const double);
  template void Scene<3>::check_distortion();
} // namespace ausroll::scene
