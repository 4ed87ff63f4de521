#include <ausroll/adaptivity/refinement_indicators.h>
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
#include <tuple>

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
      , kinematics(prm.model.planar_model, prm.model.thickness)
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
                                 [this](const double n) { check_sizes(parameters, n, dim); });
      if (resuming)
        checkpoint_directory = io::load_checkpoint_mesh(system, parameters.entries, dir);
      check_sizes(parameters, system.triangulation.n_global_active_cells(), dim);
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
      if (dim == 2 && parameters.contact.curvature_tangent)
        equilibrium->curvature_tangent = &curved_die_tangent;
      system.setup_system();
      setup_dof_dependents();
      system.initialize_material_points(assembler->quadrature().size());
      setup_thermal();
      if (!resuming && parameters.phases.enabled)
        initialize_carbon(); // its range errors before the output directory exists
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
  void Scene<dim>::setup_dof_dependents()
  {
    linear_solver.set_rigid_body_modes(system.dof_handler, system.mapping);
    contact.setup(
        system.dof_handler,
        system.mapping,
        [this](const Point<dim> &x) { return kinematics.volume_factor(x); },
        system.min_cell_diameter);
    if (contact.active())
    {
      // The curvature tangent is planar (2D only).
      if constexpr (dim == 2)
        curved_die_tangent.setup(system.mapping, system.dof_handler);
      non_candidate_penetration.setup(system.mapping, system.dof_handler);
    }
  }

  template <int dim>
  void Scene<dim>::setup_postprocessing()
  {
    if (!postprocessors)
    {
      const io::PostprocessorContext context{parameters.output,
                                             parameters.postprocess,
                                             parameters.loading.end_time,
                                             parameters.material.yield_stress,
                                             parameters.model.quadrature_points,
                                             thermal != nullptr,
                                             parameters.phases.enabled};
      postprocessors = io::make_standard_postprocessors<dim>(context, comm);
    }
    postprocessors->initialize(postprocess_input());
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
      // Equilibrium on the new mesh at the same time (no load change).
      const solver::NewtonResult result = newton.solve(*equilibrium, newton_log);
      if (!result.converged)
        throw RunFailure("re-equilibration after mesh adaptation at t = " + std::to_string(time)
                         + " failed: " + result.reason);
      commit_step(false); // the predictor's u_n-1 stays the last step's converged state
    }
    return true;
  }

  template <int dim>
  void Scene<dim>::commit_step(const bool new_step)
  {
    system.commit_step(new_step);
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

  template <int dim>
  bool Scene<dim>::add_penetrating_boundaries()
  {
    if (!contact.active() || !parameters.contact.add_penetrating_boundaries)
      return false;
    const auto p = non_candidate_penetration.find_crossing(contact,
                                                           system.solution_ghosted,
                                                           time,
                                                           system.step_start,
                                                           step_start_time,
                                                           1e-2 * system.min_cell_diameter,
                                                           comm);
    if (!p.found)
      return false;
    // A boundary with prescribed displacements (a symmetry axis, a clamp) is not made a
    // contact candidate: its constraints would conflict; the warning of accept_step() names it.
    for (const auto &c : parameters.boundary_conditions.conditions)
      if (c.id == p.boundary
          && (c.type == mechanics::BoundaryConditionType::fixed
              || c.type == mechanics::BoundaryConditionType::displacement))
        return false;
    log << "  note: "
        << contact::NonCandidatePenetration<dim>::describe(
               p, contact.die(p.die).name, step_number + 1, time)
        << "; it is now a candidate of that die (Contact/Penetrating boundaries = add), and the "
           "step is solved again. Add "
        << p.boundary << " to Contact/Die " << p.die
        << "/Candidate boundaries to say so in the input" << std::endl;
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
                                  step.time / parameters.loading.end_time,
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
    if (contact.active())
      for (unsigned int k = 0; k < contact.n_dies(); ++k)
      {
        const auto c = contact.die_contact(k);
        die_touched[k] = die_touched[k] || c.n_stick + c.n_slip > 0;
        run_totals.record_force(k, contact.die(k).name, c.force.norm(), step.time);
      }

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
    if (interval > 0 && step_number % interval == 0)
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
      initialize_temperature();
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
          initialize_carbon();
      }
      solver::NewtonResult initial;
      initial.converged = true;
      history->add_row(postprocessors->history_row(postprocess_input(&initial, 0)));
      write_output();
    }

    die_touched.assign(contact.active() ? contact.n_dies() : 0, false);
    start_fraction = time / parameters.loading.end_time; // done before this process started
    eta.start(start_fraction, wall_clock.wall_time());
    smallest_extent = system.smallest_extent();
    large_displacement_warned = !model->is_small_strain();

    stepper.run(*this, time, dt, step_number);
    write_output();

    // the summary: also at Verbosity = quiet
    ConditionalOStream summary_log(
        std::cout,
        io::prints(parameters.output.verbosity,
                   {Verbosity::quiet, Verbosity::normal, Verbosity::verbose},
                   rank));
    io::write_run_summary(summary_log,
                          run_totals,
                          stepper.solve_count.per_step.size(),
                          stepper.solve_count.accepted(),
                          stepper.solve_count.median(),
                          stepper.solve_count.discarded,
                          wall_clock.wall_time(),
                          comm);
    io::write_run_footer(summary_log,
                         step_number,
                         wall_clock.wall_time(),
                         parameters.output.directory,
                         parameters.output.write_vtu);
    if (parameters.output.verbosity != io::Verbosity::regression
        && parameters.output.verbosity != io::Verbosity::quiet)
      timer->print_summary();
    regression_log << "finished: " << step_number << " steps" << std::endl;

    // A die that never touched the workpiece is a set-up error (wrong position, feed or
    // direction): everything is written, but the run must not look like a forming result. If no
    // die touched, the run fails; a die untouched beside others that did (a shortened run of a
    // scene whose later die comes in later) is a warning.
    if (!resuming && !die_touched.empty())
    {
      const bool any_touched
          = std::find(die_touched.begin(), die_touched.end(), true) != die_touched.end();
      for (unsigned int k = 0; k < die_touched.size(); ++k)
        if (!die_touched[k])
        {
          const std::string message
              = "Contact/Die " + std::to_string(k) + " (" + contact.die(k).name
                + ") never touched the workpiece: no node was in contact with it at the end of "
                  "any of the "
                + std::to_string(step_number)
                + " steps, so its force is zero throughout (the output is complete); check its "
                  "position and Contact/Die "
                + std::to_string(k) + "/Motion";
          if (!any_touched)
            throw RunFailure(message);
          log << "warning: " << message << std::endl;
        }
    }
  }

  template class Scene<2>;
  template class Scene<3>;
} // namespace ausroll::scene
