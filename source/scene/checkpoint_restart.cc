/**
 * @file checkpoint_restart.cc
 * The checkpoint members of Scene (as ASPECT keeps Simulator's in its own file): the run state
 * that a resume needs besides mesh, vectors and material points (io/run_checkpoint.h).
 */
#include <ausroll/core/exceptions.h>
#include <ausroll/io/run_checkpoint.h>
#include <ausroll/scene/scene.h>

namespace ausroll::scene
{
  using namespace dealii;

  template <int dim>
  void Scene<dim>::write_checkpoint(const double dt)
  {
    TimerOutput::Scope scope(*timer, "checkpoint");
    const io::RunState state{time,
                             step_number,
                             dt,
                             stepper.last_step_size,
                             output_counter,
                             last_output_step,
                             equilibrium->largest_reference_force,
                             contact.pack_state(),
                             postprocessors->vtu_records()};
    io::write_checkpoint(system,
                         *point_transfer,
                         state,
                         parameters.entries,
                         parameters.output.directory,
                         thermal.get());
    log << "  checkpoint written after step " << step_number << std::endl;
  }

  template <int dim>
  double Scene<dim>::restore_checkpoint_state()
  {
    const io::RunState state = io::read_run_state(checkpoint_directory);
    time = state.time;
    step_number = state.step;
    output_counter = state.output_counter;
    last_output_step = state.last_output_step;
    equilibrium->largest_reference_force = state.largest_reference_force;
    stepper.last_step_size = state.last_step_size;
    contact.set_time(time);
    contact.update_geometry(system.solution_ghosted, false);
    contact.unpack_state(state.contact);
    postprocessors->set_vtu_records(state.vtu_records);
    history = io::History::resume(comm, parameters.output.directory + "/history.csv", step_number);
    // Reactions and material points of the restored state (no solve: it is in equilibrium).
    std::string message;
    if (!equilibrium->assemble(false, message))
      throw RunFailure("resumed state: " + message);
    log << "  resumed from " << checkpoint_directory << " at step " << step_number
        << ", t = " << time << std::endl;
    return state.step_size;
  }

  template void   Scene<2>::write_checkpoint(const double);
  template double Scene<2>::restore_checkpoint_state();
  template void   Scene<3>::write_checkpoint(const double);
  template double Scene<3>::restore_checkpoint_state();
} // namespace ausroll::scene
