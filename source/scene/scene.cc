#include <ausroll/core/exceptions.h>
#include <ausroll/geometry/workpiece.h>
#include <ausroll/io/output_directory.h>
#include <ausroll/io/postprocess/standard_set.h>
#include <ausroll/io/run_checkpoint.h>
#include <ausroll/io/run_log.h>
#include <ausroll/mechanics/distortion_check.h>
#include <ausroll/scene/scene.h>
#include <ausroll/scene/setup_checks.h>

#include <algorithm>

#include <deal.II/base/mpi.h>

namespace ausroll::scene
{
  using namespace dealii;
  using io::Verbosity;

  template <int dim>
  Scene<dim>::Scene(const SceneParameters &prm,
                    const MPI_Comm         comm,
                    const bool             resume,
                    const bool             check_only)
      : parameters(prm)
      , comm(comm)
      , resuming(resume)
      , checking(check_only)
      , rank(Utilities::MPI::this_mpi_process(comm))
      , log(std::cout,
            io::prints(prm.output.verbosity, {Verbosity::normal, Verbosity::verbose}, rank))
      , newton_log(std::cout, io::prints(prm.output.verbosity, {Verbosity::verbose}, rank))
      , regression_log(std::cout, io::prints(prm.output.verbosity, {Verbosity::regression}, rank))
      , timer(std::make_unique<TimerOutput>(comm, log, TimerOutput::never, TimerOutput::wall_times))
      , system(comm, prm.model.degree)
      , kinematics(prm.model, system.out_of_plane.configure(prm.model, dim))
      , model(material::create_constitutive_model(
            prm.model.kinematics,
            prm.material,
            prm.model.planar_model == mechanics::PlanarModel::plane_stress,
            prm.thermal.enabled ? &prm.thermal.expansion : nullptr,
            prm.phases.enabled ? &prm.phases : nullptr))
      , boundary_conditions(prm.boundary_conditions)
      , contact(prm.contact, contact::friction_context(prm.material))
      , contact_strategy(contact::make_status_strategy(prm.contact, contact, contact.active()))
      , linear_solver(prm.solver.linear)
      , newton(prm.solver)
      , stepper(prm.loading, prm.output.directory, log, newton_log)
      , distortion(prm.loading.volume_change_limit)
  {
    if (parameters.stages.declared())
      stepper.set_stages(&parameters.stages);
    // An error while setting up (bad mesh file, implausible die, ...) is caught here so that
    // the timer is destroyed while no exception is in flight (it would print an MPI warning).
    try
    {
      TimerOutput::Scope scope(*timer, "setup");
      const std::string &dir = parameters.output.directory;
      // When resuming: the coarse mesh, then the refined, partitioned mesh of the checkpoint,
      // unless the entries that made that mesh were changed.
      geometry::create_workpiece(parameters.geometry,
                                 system.triangulation,
                                 !resuming,
                                 [this](const double n) { check_sizes<dim>(parameters, n); });
      if (resuming)
        checkpoint_directory = io::load_checkpoint_mesh(system, parameters.entries, dir);
      check_sizes<dim>(parameters, system.triangulation.n_global_active_cells());
      assembler = std::make_unique<mechanics::Assembler<dim>>(system.mapping,
                                                              system.fe,
                                                              parameters.model.quadrature_points,
                                                              kinematics,
                                                              *model,
                                                              boundary_conditions,
                                                              parameters.model.volumetric_locking);
      equilibrium = std::make_unique<solver::EquilibriumProblem<dim>>(system,
                                                                      *assembler,
                                                                      boundary_conditions,
                                                                      contact,
                                                                      *contact_strategy,
                                                                      linear_solver,
                                                                      time,
                                                                      *timer,
                                                                      newton_log);
      system.setup_system();
      setup_dof_dependents();
      system.initialize_material_points(assembler->quadrature().size());
      setup_thermal();
      if (!resuming && parameters.phases.enabled)
        initialize_phases(); // its input errors before the output directory exists
      point_transfer = std::make_unique<adaptivity::MaterialPointTransfer<dim>>(
          system.triangulation,
          system.material_points,
          assembler->quadrature(),
          parameters.adaptivity.polynomial_transfer ? adaptivity::TransferMethod::polynomial
                                                    : adaptivity::TransferMethod::nearest_point,
          [this](material::MaterialState &state) { model->make_admissible(state); });
      if (resuming)
        io::load_checkpoint_vectors(system, *point_transfer, checkpoint_directory, thermal.get());
      setup_postprocessing();

      if (!resuming)
      {
        // Input errors found here leave no output directory behind.
        check_setup(parameters, system.triangulation, boundary_conditions, contact);
        if (!checking)
        {
          io::prepare_output_directory(dir, parameters.output.overwrite, comm);
          io::write_parameter_copy(dir, parameters.effective_parameters, comm);
        }
      }
      if (!checking)
        postprocessors->open_vtu_writer(dir);
    }
    catch (...)
    {
      timer.reset();
      throw;
    }
  }

  template <int dim>
  void Scene<dim>::setup_postprocessing()
  {
    if (!postprocessors)
    {
      io::PostprocessorContext context{parameters.output,
                                       parameters.postprocess,
                                       parameters.loading.end_time,
                                       parameters.material.yield_stress.min_value(),
                                       parameters.model.quadrature_points,
                                       thermal != nullptr,
                                       parameters.phases.enabled,
                                       parameters.phases.has_bainite(),
                                       system.out_of_plane.active};
      for (const solver::Stage &stage : parameters.stages.stages)
        context.stage_end_times.push_back(stage.end_time);
      postprocessors = io::make_standard_postprocessors<dim>(context, comm);
    }
    postprocessors->initialize(postprocess_input());
  }

  template <int dim>
  void Scene<dim>::commit_step(const bool new_step)
  {
    system.commit_step(new_step);
    model->set_step_length(0.); // until the next step: no kinetics in re-equilibration, output
    if (thermal)
      thermal->commit();
    contact.commit(new_step);
    equilibrium->commit();
  }

  template <int dim>
  io::PostprocessInput<dim> Scene<dim>::postprocess_input(const solver::NewtonResult *result,
                                                          const unsigned int cutbacks) const
  {
    io::PostprocessInput<dim> input{system.mapping,
                                    system.dof_handler,
                                    system.solution_ghosted,
                                    system.residual,
                                    system.material_points,
                                    *model,
                                    boundary_conditions,
                                    contact,
                                    time,
                                    step_number,
                                    result ? result->iterations : 0,
                                    cutbacks,
                                    wall_clock.wall_time()};
    input.thermal = thermal.get();
    input.out_of_plane = &system.out_of_plane;
    return input;
  }

  template <int dim>
  void Scene<dim>::write_output()
  {
    if (last_output_step == static_cast<int>(step_number))
      return;
    TimerOutput::Scope scope(*timer, "output");
    postprocessors->write_output(postprocess_input(), parameters.output.directory, output_counter);
    ++output_counter;
    last_output_step = step_number;
  }

  template <int dim>
  std::string Scene<dim>::keep_last_converged(const double t_start)
  {
    time = t_start;
    system.restore_step_start();
    // node positions and gaps of the converged state, not of the failed iterate
    contact.set_time(time);
    contact.update_geometry(system.solution_ghosted, false);
    write_output();
    return distortion.warning();
  }

  template <int dim>
  bool Scene<dim>::add_penetrating_boundaries()
  {
    if (!contact.active() || !parameters.contact.add_penetrating_boundaries)
      return false;
    const auto p = non_candidate_penetration.boundary_to_add(
        contact,
        system.solution_ghosted,
        time,
        system.step_start,
        step_start_time,
        1e-2 * system.min_cell_diameter,
        parameters.boundary_conditions.held_boundaries(),
        comm);
    if (!p.found)
      return false;
    log << "  note: "
        << contact::NonCandidatePenetration<dim>::added_note(
               p, contact.die(p.die).name, step_number + 1, time)
        << std::endl;
    // The committed statuses carry over to the new set of contact nodes by position.
    const std::vector<double> state = contact.pack_state();
    contact.add_candidate_boundary(p.die, p.boundary);
    setup_dof_dependents();
    contact.unpack_state(state);
    contact_strategy->restart_step();
    return true;
  }

  template <int dim>
  contact::StepDecision Scene<dim>::end_of_step(const double dt)
  {
    if (add_penetrating_boundaries())
      return contact::StepDecision{false, 1.};
    return contact_strategy->end_of_step(dt, parameters.loading.end_time, newton_log);
  }

  template <int dim>
  unsigned int Scene<dim>::accept_step(const solver::LoadStep &step)
  {
    const unsigned int status_changes = contact.active() ? contact.n_changed_statuses() : 0;
    if (thermal && !thermal_current)
      thermal_step(step);
    commit_step();
    step_number = step.number;
    const io::HistoryRow row
        = postprocessors->history_row(postprocess_input(&step.result, step.cutbacks));
    history->add_row(row);

    // Small strain is meant for displacements small against the body: warn (once) otherwise.
    if (!large_displacement_warned)
      large_displacement_warned = io::warn_large_displacement(
          step_number, system.solution.linfty_norm(), smallest_extent, rank);
    const auto [n_stick, n_slip]
        = contact.active() ? contact.n_stick_slip() : std::pair<unsigned int, unsigned int>();
    const io::StepSummary summary{step_number,
                                  step.time,
                                  parameters.stages.progress(step.time, parameters.loading),
                                  start_fraction,
                                  step.result,
                                  step.cutbacks,
                                  contact.active(),
                                  n_stick,
                                  n_slip,
                                  system.dof_handler.n_dofs(),
                                  wall_clock.wall_time()};
    eta.add(summary.fraction, summary.elapsed);
    io::write_step_line(log, summary, eta.eta());
    io::write_regression_line(regression_log, step_number, row);

    run_totals.cutbacks += step.cutbacks;
    run_totals.record_die_forces(contact, step.time);
    die_touches.record(contact);

    check_distortion();
    if (contact.active())
    {
      // a boundary that may not touch a die passes through it
      const std::string penetration
          = non_candidate_penetration.check(contact,
                                            system.solution_ghosted,
                                            step.time,
                                            step_number,
                                            1e-2 * system.min_cell_diameter,
                                            comm);
      if (!penetration.empty())
        log << "  warning: " << penetration << std::endl;
    }

    const double t_end = parameters.loading.end_time;
    if (parameters.adaptivity.interval > 0 && step_number % parameters.adaptivity.interval == 0
        && step.time < t_end * (1. - 1e-12))
      adapt_mesh(std::min(t_end, step.time + step.step_size));

    const unsigned int interval = parameters.output.interval;
    // and at the end of every process stage (the rolled state, the cooled state, ...)
    if ((interval > 0 && step_number % interval == 0)
        || (parameters.stages.declared() && parameters.stages.ends_stage(step.time)))
      write_output();
    if (parameters.checkpoint.interval > 0 && step_number % parameters.checkpoint.interval == 0)
      write_checkpoint(step.step_size);
    if (!resuming)
      io::abort_if_asked(parameters.checkpoint, step_number, log);
    return status_changes;
  }

  template <int dim>
  void Scene<dim>::run()
  {
    const double      nominal_dt = stepper.nominal_step_size();
    const std::string fe
        = "FE_Q(" + std::to_string(parameters.model.degree) + ") x " + std::to_string(dim);
    const bool f_bar = parameters.model.volumetric_locking == mechanics::VolumetricLocking::f_bar;
    io::write_run_header(log,
                         regression_log,
                         parameters.name,
                         Utilities::MPI::n_mpi_processes(comm),
                         system.triangulation.n_global_active_cells(),
                         system.dof_handler.n_dofs(),
                         fe,
                         material::to_string(parameters.model.kinematics)
                             + (f_bar ? ", F-bar" : ""),
                         parameters.output.directory);

    double dt = nominal_dt;
    if (resuming)
      dt = restore_checkpoint_state();
    else
    {
      // Initial (undeformed) state.
      history = std::make_unique<io::History>(comm, parameters.output.directory + "/history.csv");
      system.step_start = 0.;
      system.start_step(0.); // solution = step_start
      time = 0.;
      if (!parameters.phases.enabled)
        initialize_temperature(); // (with phases: done by initialize_phases() above)
      std::string message;
      if (!equilibrium->assemble(false, message))
        throw RunFailure("initial state: " + message);
      contact.commit(); // gaps of the undeformed state start the load-increment ratio
      for (unsigned int cycle = 0; cycle < parameters.adaptivity.initial_cycles; ++cycle)
        if (!adapt_mesh(std::min(nominal_dt, parameters.loading.end_time)))
          break;
      if (parameters.adaptivity.initial_cycles > 0)
      {
        // the initial fields on the refined mesh, not interpolated
        initialize_temperature();
        if (parameters.phases.enabled)
          initialize_phases();
      }
      solver::NewtonResult initial;
      initial.converged = true;
      history->add_row(postprocessors->history_row(postprocess_input(&initial, 0)));
      write_output();
    }

    start_fraction = parameters.stages.progress(time, parameters.loading); // done before
    eta.start(start_fraction, wall_clock.wall_time());
    smallest_extent = system.smallest_extent();
    large_displacement_warned = !model->is_small_strain();

    stepper.run(*this, time, dt, step_number);
    write_output();
    stepper.solve_count.assemblies = newton.assembly_count();
    stepper.solve_count.reused_assemblies = system.assembly_cache.hits;

    io::write_run_end(parameters.output,
                      rank,
                      run_totals,
                      stepper.solve_count,
                      step_number,
                      wall_clock.wall_time(),
                      *timer,
                      regression_log,
                      comm);

    // A die that never touched the workpiece (contact/die_touch.h): the run fails if no die
    // touched, a die untouched beside others that did is a warning.
    if (!resuming)
      for (const std::string &warning : die_touches.untouched_warnings(contact, step_number))
        log << "warning: " << warning << std::endl;
  }

  template class Scene<2>;
  template class Scene<3>;
} // namespace ausroll::scene
