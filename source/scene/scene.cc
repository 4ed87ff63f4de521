#include <ausroll/adaptivity/refinement_indicators.h>
#include <ausroll/core/exceptions.h>
#include <ausroll/core/parse_utilities.h>
#include <ausroll/geometry/workpiece.h>
#include <ausroll/io/checkpoint.h>
#include <ausroll/io/output_directory.h>
#include <ausroll/io/postprocess/die_forces.h>
#include <ausroll/io/postprocess/field_files.h>
#include <ausroll/io/postprocess/material_state.h>
#include <ausroll/io/postprocess/monitor_points.h>
#include <ausroll/io/postprocess/reaction_forces.h>
#include <ausroll/io/postprocess/step_statistics.h>
#include <ausroll/scene/scene.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <regex>
#include <sstream>

namespace ausroll::scene
{
  using namespace dealii;

  namespace
  {
    using io::Verbosity;

    bool prints(const Verbosity v, std::initializer_list<Verbosity> set, const unsigned int rank)
    {
      if (rank != 0)
        return false;
      for (const Verbosity s : set)
        if (s == v)
          return true;
      return false;
    }

    /**
     * Range of the volume change J = det F over the quadrature points of the converged state, with
     * the points where the extremes lie (same on all ranks). Plastic flow is isochoric and the
     * elastic volume change of metals is below 1 %, so J far from 1 at a point means that the
     * element is folding, not that the material is compressed (F-bar leaves the pointwise J free
     * and only the cell mean physical).
     */
    template <int dim>
    struct VolumeChangeRange
    {
      double     min_J = std::numeric_limits<double>::max();
      double     max_J = 0.;
      Point<dim> where_min, where_max;
    };

    template <int dim>
    VolumeChangeRange<dim> volume_change_range(const Mapping<dim>                     &mapping,
                                               const DoFHandler<dim>                  &dof_handler,
                                               const Quadrature<dim>                  &quadrature,
                                               const mechanics::PlanarKinematics<dim> &kinematics,
                                               const TrilinosWrappers::MPI::Vector    &u)
    {
      VolumeChangeRange<dim>           range;
      FEValues<dim>                    fe_values(mapping,
                              dof_handler.get_fe(),
                              quadrature,
                              update_values | update_gradients | update_quadrature_points);
      const FEValuesExtractors::Vector displacement(0);
      std::vector<Tensor<2, dim>>      grad_u(quadrature.size());
      std::vector<Tensor<1, dim>>      u_values(quadrature.size());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[displacement].get_function_gradients(u, grad_u);
          fe_values[displacement].get_function_values(u, u_values);
          for (unsigned int q = 0; q < quadrature.size(); ++q)
          {
            const Point<dim> &X = fe_values.quadrature_point(q);
            const double      J
                = determinant(kinematics.deformation_gradient(grad_u[q], u_values[q], X));
            if (J < range.min_J)
            {
              range.min_J = J;
              range.where_min = X;
            }
            if (J > range.max_J)
            {
              range.max_J = J;
              range.where_max = X;
            }
          }
        }
      // the extremes and their places from the rank that holds them
      const MPI_Comm     comm = dof_handler.get_communicator();
      const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
      const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
      const double       global_min = Utilities::MPI::min(range.min_J, comm);
      const double       global_max = Utilities::MPI::max(range.max_J, comm);
      const unsigned int min_rank
          = Utilities::MPI::min(range.min_J == global_min ? rank : n_ranks, comm);
      const unsigned int max_rank
          = Utilities::MPI::min(range.max_J == global_max ? rank : n_ranks, comm);
      range.where_min = Utilities::MPI::broadcast(comm, range.where_min, min_rank);
      range.where_max = Utilities::MPI::broadcast(comm, range.where_max, max_rank);
      range.min_J = global_min;
      range.max_J = global_max;
      return range;
    }

    std::string format_seconds(const double s)
    {
      std::ostringstream out;
      out << std::fixed << std::setprecision(s < 10 ? 1 : 0) << s << " s";
      return out.str();
    }
  } // namespace

  template <int dim>
  Scene<dim>::Scene(const SceneParameters &prm, const MPI_Comm comm, const bool resume)
      : parameters(prm)
      , comm(comm)
      , resuming(resume)
      , rank(Utilities::MPI::this_mpi_process(comm))
      , log(std::cout, prints(prm.output.verbosity, {Verbosity::normal, Verbosity::verbose}, rank))
      , newton_log(std::cout, prints(prm.output.verbosity, {Verbosity::verbose}, rank))
      , regression_log(std::cout, prints(prm.output.verbosity, {Verbosity::regression}, rank))
      , timer(std::make_unique<TimerOutput>(comm, log, TimerOutput::never, TimerOutput::wall_times))
      , triangulation(comm,
                      typename Triangulation<dim>::MeshSmoothing(
                          Triangulation<dim>::smoothing_on_refinement
                          | Triangulation<dim>::smoothing_on_coarsening))
      , fe(FE_Q<dim>(prm.model.degree), dim)
      , mapping(prm.model.degree)
      , dof_handler(triangulation)
      , kinematics(prm.model.planar_model, prm.model.thickness)
      , model(material::create_constitutive_model(prm.model.kinematics,
                                                  prm.material,
                                                  prm.model.planar_model
                                                      == mechanics::PlanarModel::plane_stress))
      , boundary_conditions(prm.boundary_conditions)
      , contact(prm.contact)
      , contact_strategy(contact::make_status_strategy(prm.contact, contact, contact.active()))
      , linear_solver(prm.solver.linear)
      , newton(prm.solver)
  {
    // An error while setting up (bad mesh file, implausible die, ...) is caught here so that
    // the timer is destroyed while no exception is in flight (it would print an MPI warning).
    try
    {
      TimerOutput::Scope     scope(*timer, "setup");
      const std::string     &dir = parameters.output.directory;
      io::CheckpointMetadata meta;
      if (resuming)
      {
        // The coarse mesh, then the refined, partitioned mesh of the checkpoint, unless the
        // entries that made that mesh were changed.
        geometry::create_workpiece(parameters.geometry, triangulation, /*refine=*/false);
        checkpoint_directory = io::CheckpointDirectory(dir, comm).latest();
        meta.read(checkpoint_directory + "/metadata.txt");
        for (const std::string &warning :
             io::compare_resume_parameters(meta, parameters.entries, checkpoint_directory))
          if (rank == 0)
            std::cerr << "ausroll: warning: " << warning << std::endl;
        triangulation.load(checkpoint_directory + "/mesh");
      }
      else
        geometry::create_workpiece(parameters.geometry, triangulation);
      geometry::require_dof_estimate(
          triangulation.n_global_active_cells(), parameters.model.degree, dim);
      assembler = std::make_unique<mechanics::Assembler<dim>>(mapping,
                                                              fe,
                                                              parameters.model.quadrature_points,
                                                              kinematics,
                                                              *model,
                                                              boundary_conditions,
                                                              parameters.model.volumetric_locking);
      setup_system();
      material_points.initialize(
          triangulation.begin_active(), triangulation.end(), assembler->quadrature().size());
      point_transfer = std::make_unique<adaptivity::MaterialPointTransfer<dim>>(
          triangulation,
          material_points,
          assembler->quadrature(),
          parameters.adaptivity.polynomial_transfer ? adaptivity::TransferMethod::polynomial
                                                    : adaptivity::TransferMethod::nearest_point,
          [this](material::MaterialState &state) { model->make_admissible(state); });
      if (resuming)
      {
        // Same order as in write_checkpoint(): solution first, then the material points.
        parallel::distributed::SolutionTransfer<dim, TrilinosWrappers::MPI::Vector> transfer(
            dof_handler);
        // with the converged solution before it (the predictor's), if the checkpoint has it
        std::vector<TrilinosWrappers::MPI::Vector *> vectors{&solution};
        if (meta.values.count("previous_solution") > 0)
          vectors.push_back(&previous_start);
        transfer.deserialize(vectors);
        solution_ghosted = solution;
        step_start = solution;
        point_transfer->prepare();
        point_transfer->unpack();
      }
      setup_postprocessing();

      if (!resuming)
      {
        // Input errors found here leave no output directory behind.
        check_setup();
        io::prepare_output_directory(dir, parameters.output.overwrite, comm);
      }
      postprocessors->open_vtu_writer(dir);
    }
    catch (...)
    {
      timer.reset();
      throw;
    }
  }

  template <int dim>
  void Scene<dim>::write_checkpoint(const double dt)
  {
    TimerOutput::Scope            scope(*timer, "checkpoint");
    const io::CheckpointDirectory checkpoints(parameters.output.directory, comm);
    const std::string             dir = checkpoints.begin_write();

    parallel::distributed::SolutionTransfer<dim, TrilinosWrappers::MPI::Vector> transfer(
        dof_handler);
    // the converged solution before this one too: the predictor of the next step needs it
    TrilinosWrappers::MPI::Vector previous_ghosted(owned_dofs, relevant_dofs, comm);
    previous_ghosted = previous_start;
    transfer.prepare_for_serialization(
        std::vector<const TrilinosWrappers::MPI::Vector *>{&solution_ghosted, &previous_ghosted});
    point_transfer->prepare();
    triangulation.save(dir + "/mesh");

    io::CheckpointMetadata meta;
    meta.values["time"] = {time};
    meta.values["step"] = {double(step_number)};
    meta.values["dt"] = {dt};
    meta.values["last_step_size"] = {last_step_size};
    meta.values["previous_solution"] = {1.};
    meta.set_parameters(parameters.entries);
    meta.values["output_counter"] = {double(output_counter)};
    meta.values["last_output_step"] = {double(last_output_step)};
    meta.values["largest_reference_force"] = {largest_reference_force};
    meta.values["contact"] = contact.pack_state();
    std::vector<double> output_times;
    std::string         output_files;
    for (const auto &[t, file] : postprocessors->vtu_records())
    {
      output_times.push_back(t);
      output_files += (output_files.empty() ? "" : " ") + file;
    }
    meta.values["output_times"] = output_times;
    meta.strings["output_files"] = output_files;
    if (rank == 0)
      meta.write(dir + "/metadata.txt");
    checkpoints.commit();
    log << "  checkpoint written after step " << step_number << std::endl;
  }

  template <int dim>
  double Scene<dim>::restore_checkpoint_state()
  {
    io::CheckpointMetadata meta;
    meta.read(checkpoint_directory + "/metadata.txt");
    time = meta.get("time");
    step_number = static_cast<unsigned int>(meta.get("step"));
    output_counter = static_cast<unsigned int>(meta.get("output_counter"));
    last_output_step = static_cast<int>(meta.get("last_output_step"));
    largest_reference_force = meta.get("largest_reference_force");
    if (meta.values.count("last_step_size") > 0)
      last_step_size = meta.get("last_step_size");
    contact.set_time(time);
    contact.update_geometry(solution_ghosted, false);
    contact.unpack_state(meta.values["contact"]);
    std::vector<std::pair<double, std::string>> records;
    std::istringstream                          files(meta.strings["output_files"]);
    for (const double t : meta.values["output_times"])
    {
      std::string file;
      files >> file;
      records.emplace_back(t, file);
    }
    postprocessors->set_vtu_records(records);
    history = io::History::resume(comm, parameters.output.directory + "/history.csv", step_number);
    // Reactions and material points of the restored state (no solve: it is in equilibrium).
    std::string message;
    if (!assemble(false, message))
      throw RunFailure("resumed state: " + message);
    log << "  resumed from " << checkpoint_directory << " at step " << step_number
        << ", t = " << time << std::endl;
    return meta.get("dt");
  }

  template <int dim>
  void Scene<dim>::setup_system()
  {
    dof_handler.distribute_dofs(fe);
    owned_dofs = dof_handler.locally_owned_dofs();
    relevant_dofs = DoFTools::extract_locally_relevant_dofs(dof_handler);

    hanging_constraints.clear();
    hanging_constraints.reinit(relevant_dofs);
    DoFTools::make_hanging_node_constraints(dof_handler, hanging_constraints);
    hanging_constraints.close();

    DynamicSparsityPattern dsp(relevant_dofs);
    DoFTools::make_sparsity_pattern(
        dof_handler, dsp, hanging_constraints, /*keep_constrained=*/true);
    SparsityTools::distribute_sparsity_pattern(dsp, owned_dofs, comm, relevant_dofs);
    // the kept factorisation refers to the old matrix: release it before that matrix goes
    linear_solver.matrix_pattern_changed();
    system_matrix.reinit(owned_dofs, owned_dofs, dsp, comm);

    for (auto *v : {&solution,
                    &step_start,
                    &previous_start,
                    &newton_start,
                    &increment,
                    &rhs,
                    &residual,
                    &free_residual,
                    &external_force})
      v->reinit(owned_dofs, comm);
    solution_ghosted.reinit(owned_dofs, relevant_dofs, comm);
    residual_ghosted.reinit(owned_dofs, relevant_dofs, comm);

    double h_min = std::numeric_limits<double>::max();
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        h_min = std::min(h_min, cell->minimum_vertex_distance());
    min_cell_diameter = Utilities::MPI::min(h_min, comm);

    linear_solver.set_rigid_body_modes(dof_handler, mapping);
    contact.setup(
        dof_handler,
        mapping,
        [this](const Point<dim> &x) { return kinematics.volume_factor(x); },
        min_cell_diameter);
  }

  template <int dim>
  void Scene<dim>::setup_postprocessing()
  {
    if (!postprocessors)
    {
      // The order of these lines is the order of the history columns and output files.
      namespace pp = io::postprocess;
      const io::PostprocessParameters &p = parameters.postprocess;
      postprocessors = std::make_unique<io::PostprocessorSet<dim>>(parameters.output, comm);
      postprocessors->add(std::make_unique<pp::StepStatistics<dim>>(parameters.loading.end_time));
      postprocessors->add(std::make_unique<pp::AppliedPressures<dim>>());
      postprocessors->add(std::make_unique<pp::MonitorPoints<dim>>(p.monitor_points));
      postprocessors->add(std::make_unique<pp::ReactionForces<dim>>(
          parse_unsigned_list(p.reaction_boundaries, "Postprocess/Reaction boundaries")));
      postprocessors->add(std::make_unique<pp::DieForces<dim>>());
      postprocessors->add(std::make_unique<pp::YieldExcess<dim>>(parameters.material.yield_stress));
      postprocessors->add(std::make_unique<pp::LineProbeFiles<dim>>(
          p.line_probes, parameters.model.quadrature_points));
      postprocessors->add(std::make_unique<pp::BoundaryProfileFiles<dim>>(p.boundary_profile));
      postprocessors->add(std::make_unique<pp::ContactFiles<dim>>());
      postprocessors->add(std::make_unique<pp::CellAverages<dim>>());
    }
    postprocessors->initialize(postprocess_input());
  }

  template <int dim>
  bool Scene<dim>::adapt_mesh(const double next_time)
  {
    const adaptivity::AdaptivityParameters &p = parameters.adaptivity;
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
                                  triangulation,
                                  mapping,
                                  dof_handler,
                                  solution_ghosted,
                                  material_points,
                                  die_distance))
        return false;

      // Carry displacement, material points and contact statuses to the new mesh.
      const std::vector<double> contact_state = contact.pack_state();
      parallel::distributed::SolutionTransfer<dim, TrilinosWrappers::MPI::Vector> transfer(
          dof_handler);
      // the converged solution before this one too: the predictor of the next step extrapolates
      // from both (setup_system() zeroes it; the first step after every adaptation then had no
      // prediction, or without re-equilibration the first iterate (1 + dt / dt_prev) u_n)
      TrilinosWrappers::MPI::Vector previous_ghosted(owned_dofs, relevant_dofs, comm);
      previous_ghosted = previous_start;
      triangulation.prepare_coarsening_and_refinement();
      transfer.prepare_for_coarsening_and_refinement(
          std::vector<const TrilinosWrappers::MPI::Vector *>{&solution_ghosted, &previous_ghosted});
      point_transfer->prepare();
      triangulation.execute_coarsening_and_refinement();

      setup_system();
      point_transfer->unpack();
      TrilinosWrappers::MPI::Vector                interpolated(owned_dofs, comm);
      TrilinosWrappers::MPI::Vector                previous_interpolated(owned_dofs, comm);
      std::vector<TrilinosWrappers::MPI::Vector *> targets{&interpolated, &previous_interpolated};
      transfer.interpolate(targets);
      hanging_constraints.distribute(interpolated);
      hanging_constraints.distribute(previous_interpolated);
      solution = interpolated;
      solution_ghosted = solution;
      step_start = solution;
      previous_start = previous_interpolated;
      rebase_material_points();
      contact.unpack_state(contact_state);
      setup_postprocessing();
    }
    log << "  mesh adapted: " << triangulation.n_global_active_cells() << " cells, "
        << dof_handler.n_dofs() << " DoFs" << std::endl;

    // Before the first step (initial refinement cycles, t = 0) nothing has been solved yet: the
    // interpolated state is the undeformed one and Newton would only chase round-off.
    if (p.reequilibrate && time > 0.)
    {
      // Equilibrium on the new mesh at the same time (no load change).
      const solver::NewtonResult result = newton.solve(*this, newton_log);
      if (!result.converged)
        throw RunFailure("re-equilibration after mesh adaptation at t = " + std::to_string(time)
                         + " failed: " + result.reason);
      // the predictor's u_n-1 stays the converged state of the last step, not the interpolated
      // state of this one (their difference is only the re-equilibration)
      const TrilinosWrappers::MPI::Vector previous_converged = previous_start;
      commit_step();
      previous_start = previous_converged;
    }
    return true;
  }

  template <int dim>
  void Scene<dim>::rebase_material_points()
  {
    // with the deformation gradient the material sees (F-bar included): re-basing with the plain
    // F left every F-bar state off equilibrium by the difference, growing at every adaptation
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
      {
        const std::vector<Tensor<2, 3>> F
            = assembler->material_deformation_gradients(cell, solution_ghosted);
        const auto points = material_points.get_data(cell);
        for (unsigned int q = 0; q < points.size(); ++q)
        {
          model->rebase(points[q]->committed, F[q]);
          points[q]->trial = points[q]->committed;
        }
      }
  }

  template <int dim>
  void Scene<dim>::build_newton_constraints()
  {
    newton_constraints.clear();
    newton_constraints.reinit(relevant_dofs);
    newton_constraints.merge(hanging_constraints);
    boundary_conditions.add_increment_constraints(
        dof_handler, time, solution_ghosted, newton_constraints);
    double violation = 0.;
    for (const auto &line : newton_constraints.get_lines())
      if (owned_dofs.is_element(line.index))
        violation = std::max(violation, std::abs(line.inhomogeneity));
    if (contact.active())
      violation
          = std::max(violation, contact.add_constraints(solution_ghosted, newton_constraints));
    newton_constraints.close();
    last_constraint_violation = Utilities::MPI::max(violation, comm);
  }

  template <int dim>
  bool Scene<dim>::assemble(const bool with_matrix, std::string &message)
  {
    TimerOutput::Scope scope(*timer, "assembly");
    contact_strategy->begin_iterate(time);
    // Statuses that the strategy changes at this iterate (judged by the reactions of this very
    // assembly) require the constraints to be rebuilt and the system re-assembled.
    for (;;)
    {
      contact_strategy->update_geometry(solution_ghosted);
      build_newton_constraints();

      residual = 0.;
      external_force = 0.;
      free_residual = 0.;
      mechanics::AssemblyTargets targets;
      targets.residual = &residual;
      targets.external_force = &external_force;
      targets.free_residual = &free_residual;
      if (with_matrix)
      {
        system_matrix = 0.;
        rhs = 0.;
        targets.matrix = &system_matrix;
        targets.rhs = &rhs;
      }
      const mechanics::AssemblyStatus status
          = assembler->assemble(dof_handler,
                                solution_ghosted,
                                time,
                                material_points,
                                hanging_constraints,
                                newton_constraints,
                                contact.active() ? &contact.row_transforms() : nullptr,
                                targets);
      if (!status.ok)
      {
        message = status.message;
        return false;
      }
      if (!contact.active())
        break;
      residual_ghosted = residual;
      contact.compute_reactions(residual_ghosted);
      const unsigned int changes = contact_strategy->update_at_iterate();
      if (changes == 0)
        break;
      newton_log << "      contact: " << changes << " status change" << (changes > 1 ? "s" : "")
                 << ", re-assembling" << std::endl;
    }

    // Force level: external loads and reactions (residual at prescribed DoFs).
    double reaction_sq = 0.;
    for (const auto i : owned_dofs)
      if (newton_constraints.is_constrained(i) && !hanging_constraints.is_constrained(i))
        reaction_sq += residual[i] * residual[i];
    const double reaction_norm = std::sqrt(Utilities::MPI::sum(reaction_sq, comm));
    last_residual_norm = free_residual.l2_norm();
    last_reference_force = std::max(external_force.l2_norm(), reaction_norm);
    return true;
  }

  template <int dim>
  unsigned int Scene<dim>::update_constraints_at_convergence(ConditionalOStream &log)
  {
    // the reactions of the converged state (residual_ghosted of the last assembly) decide
    return contact_strategy->update_at_convergence(solution_ghosted, log);
  }

  template <int dim>
  void Scene<dim>::check_setup()
  {
    // Every boundary-id entry against the ids the mesh has.
    const auto &conditions = parameters.boundary_conditions.conditions;
    for (unsigned int i = 0; i < conditions.size(); ++i)
      geometry::require_boundary_ids(triangulation,
                                     {conditions[i].id},
                                     "Boundary conditions/Condition " + std::to_string(i)
                                         + "/Boundary id");
    for (unsigned int k = 0; k < parameters.contact.dies.size(); ++k)
      geometry::require_boundary_ids(triangulation,
                                     parameters.contact.dies[k].candidate_boundaries,
                                     "Contact/Die " + std::to_string(k) + "/Candidate boundaries");
    geometry::require_boundary_ids(triangulation,
                                   parse_unsigned_list(parameters.postprocess.reaction_boundaries,
                                                       "Postprocess/Reaction boundaries"),
                                   "Postprocess/Reaction boundaries");
    geometry::require_boundary_ids(triangulation,
                                   parameters.postprocess.boundary_profile.boundary_ids,
                                   "Postprocess/Boundary profile/Boundary ids");
    if (parameters.model.planar_model == mechanics::PlanarModel::axisymmetric)
      geometry::require_off_axis(triangulation, "Model/Planar model = axisymmetric");

    // Loads and dies at a bounded number of times (all step times for up to 256 steps): the
    // check costs the same for any Loading/Number of steps.
    const solver::LoadingParameters &loading = parameters.loading;
    const unsigned int               n_samples = std::min(loading.number_of_steps, 256u);
    std::vector<double>              times;
    for (unsigned int k = 0; k <= n_samples; ++k)
      times.push_back(loading.end_time * k / n_samples);
    boundary_conditions.check_values(triangulation, times);
    const auto box = GridTools::compute_bounding_box(triangulation);
    if (contact.active())
      contact.check_dies(
          times, box.get_boundary_points().first.distance(box.get_boundary_points().second));
  }

  template <int dim>
  bool Scene<dim>::backtrack_with_small_constraint_gaps() const
  {
    return contact_strategy->backtrack_with_small_constraint_gaps();
  }

  template <int dim>
  double Scene<dim>::residual_norm() const
  {
    return last_residual_norm;
  }

  template <int dim>
  double Scene<dim>::reference_force() const
  {
    // Forces below 1e-3 of the largest force level seen in the run are round-off noise (e.g. a die
    // just lifting off): do not ask the residual to be smaller than the run's round-off.
    return std::max(last_reference_force, 1e-3 * largest_reference_force);
  }

  template <int dim>
  double Scene<dim>::constraint_violation() const
  {
    return last_constraint_violation;
  }

  template <int dim>
  double Scene<dim>::length_scale() const
  {
    return min_cell_diameter;
  }

  template <int dim>
  double Scene<dim>::increment_residual_product() const
  {
    return increment * free_residual;
  }

  template <int dim>
  solver::LinearSolveInfo Scene<dim>::solve_for_increment()
  {
    TimerOutput::Scope scope(*timer, "linear solve");
    newton_start = solution;
    increment = 0.;
    const solver::LinearSolveInfo info = linear_solver.solve(system_matrix, increment, rhs);
    newton_constraints.distribute(increment);
    return info;
  }

  template <int dim>
  void Scene<dim>::apply_increment(const double step_length)
  {
    solution = newton_start;
    solution.add(step_length, increment);
    solution_ghosted = solution;
  }

  template <int dim>
  void Scene<dim>::commit_step()
  {
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto &point : material_points.get_data(cell))
          point->commit();
    previous_start = step_start;
    step_start = solution;
    contact.commit();
    largest_reference_force = std::max(largest_reference_force, last_reference_force);
  }

  template <int dim>
  io::PostprocessInput<dim> Scene<dim>::postprocess_input(const solver::NewtonResult *result,
                                                          const unsigned int cutbacks) const
  {
    io::PostprocessInput<dim> input{mapping,
                                    dof_handler,
                                    solution_ghosted,
                                    residual,
                                    material_points,
                                    *model,
                                    boundary_conditions,
                                    contact};
    input.time = time;
    input.step = step_number;
    input.newton_iterations = result ? result->iterations : 0;
    input.cutbacks = cutbacks;
    input.wall_seconds = wall_clock.wall_time();
    return input;
  }

  template <int dim>
  io::HistoryRow Scene<dim>::history_row(const solver::NewtonResult &result,
                                         const unsigned int          cutbacks) const
  {
    return postprocessors->history_row(postprocess_input(&result, cutbacks));
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
  double Scene<dim>::solve_step(const double          t_start,
                                double                dt,
                                solver::NewtonResult &result,
                                unsigned int         &cutbacks)
  {
    const solver::LoadingParameters &loading = parameters.loading;
    cutbacks = 0;
    time = t_start;
    contact_strategy->begin_step(solution_ghosted, t_start);
    // A step that fails with the predictor is first tried again from the converged state (the
    // extrapolation overshoots where the path turns: a fold-over corner, a node reaching a die).
    bool predict
        = loading.predictor == solver::Predictor::linear_extrapolation && last_step_size > 0.;
    for (;;)
    {
      time = t_start + dt;
      solution = step_start;
      if (predict)
      {
        // u_n + (dt / dt_prev) (u_n - u_n-1)
        const double ratio = dt / last_step_size;
        solution.add(ratio, step_start);
        solution.add(-ratio, previous_start);
      }
      solution_ghosted = solution;
      newton_log << "  step " << step_number + 1 << ", t = " << time << std::endl;
      result = newton.solve(*this, newton_log);

      if (!result.converged && predict)
      {
        predict = false;
        contact_strategy->restart_step();
        log << "  step " << step_number + 1 << " (t = " << time << "): " << result.reason
            << "; trying again without the predictor" << std::endl;
        continue;
      }
      if (!result.converged)
      {
        ++cutbacks;
        contact_strategy->restart_step();
        log << "  step " << step_number + 1 << " (t = " << time << "): " << result.reason;
        if (cutbacks > loading.max_cutbacks)
        {
          log << std::endl;
          // Keep the last converged state in memory and on disk.
          time = t_start;
          solution = step_start;
          solution_ghosted = solution;
          // node positions and gaps of the converged state, not of the failed iterate
          contact.set_time(time);
          contact.update_geometry(solution_ghosted, false);
          write_output();
          std::ostringstream msg;
          msg << "load step " << step_number + 1 << " (t = " << t_start + dt
              << ") did not converge after " << loading.max_cutbacks
              << " cutbacks: " << result.reason << ". The last converged state (step "
              << step_number << ", t = " << t_start << ") is in " << parameters.output.directory
              << "/";
          if (!distortion_warning.empty())
            msg << ". Earlier, " << distortion_warning;
          throw RunFailure(msg.str());
        }
        dt *= 0.5;
        log << "; cutting back to dt = " << dt << std::endl;
        continue;
      }
      // The strategy may end the step earlier, where a contact status changes.
      const contact::StepDecision decision
          = contact_strategy->end_of_step(dt, loading.end_time, newton_log);
      if (decision.accept)
        return time;
      dt *= decision.step_factor;
    }
  }

  template <int dim>
  void Scene<dim>::check_distortion()
  {
    const double limit = parameters.loading.volume_change_limit;
    if (limit <= 0. || !distortion_warning.empty())
      return;
    const VolumeChangeRange<dim> range = volume_change_range(
        mapping, dof_handler, assembler->quadrature(), kinematics, solution_ghosted);
    newton_log << "  volume change J = det F in [" << range.min_J << " at (" << range.where_min
               << "), " << range.max_J << " at (" << range.where_max << ")]" << std::endl;
    if (range.min_J >= limit && range.max_J <= 1. / limit)
      return;
    const bool         low = range.min_J < limit;
    std::ostringstream msg;
    msg << "the mesh folds: J = det F = " << (low ? range.min_J : range.max_J)
        << " at the quadrature point (" << (low ? range.where_min : range.where_max)
        << ") (reference coordinates) in step " << step_number << ", t = " << time
        << " (Loading/Volume change limit = " << limit
        << "); forces from here on are not mesh-converged. Refine the mesh there (Geometry/"
           "Refinement point, Local refinements), let Adaptivity refine it, or let the folding "
           "surface touch the die (Contact/Die N/Candidate boundaries)";
    distortion_warning = msg.str();
    log << "  warning: " << distortion_warning << std::endl;
    if (parameters.loading.stop_at_distortion)
    {
      write_output();
      throw RunFailure(distortion_warning + " (Loading/Stop at distorted mesh = true). The state "
                       + "of step " + std::to_string(step_number) + " is in "
                       + parameters.output.directory + "/");
    }
  }

  template <int dim>
  void Scene<dim>::run()
  {
    const solver::LoadingParameters &loading = parameters.loading;
    const double                     nominal_dt = loading.end_time / loading.number_of_steps;

    log << "ausroll: " << parameters.name << "  (" << Utilities::MPI::n_mpi_processes(comm)
        << " MPI rank" << (Utilities::MPI::n_mpi_processes(comm) > 1 ? "s" : "") << ")\n"
        << "  mesh: " << triangulation.n_global_active_cells() << " cells, " << dof_handler.n_dofs()
        << " DoFs (FE_Q(" << parameters.model.degree << ") x " << dim << ")\n"
        << "  kinematics: " << material::to_string(parameters.model.kinematics)
        << (parameters.model.volumetric_locking == mechanics::VolumetricLocking::f_bar ? ", F-bar"
                                                                                       : "")
        << "\n"
        << "  output: " << parameters.output.directory << "/" << std::endl;
    regression_log << "scene: " << parameters.name
                   << "\ncells: " << triangulation.n_global_active_cells()
                   << "  dofs: " << dof_handler.n_dofs() << std::endl;

    double dt = nominal_dt;
    if (resuming)
      dt = restore_checkpoint_state();
    else
    {
      // Initial (undeformed) state.
      history = std::make_unique<io::History>(comm, parameters.output.directory + "/history.csv");
      solution = 0.;
      solution_ghosted = solution;
      step_start = solution;
      time = 0.;
      std::string message;
      if (!assemble(false, message))
        throw RunFailure("initial state: " + message);
      contact.commit(); // gaps of the undeformed state start the load-increment ratio
      for (unsigned int cycle = 0; cycle < parameters.adaptivity.initial_cycles; ++cycle)
        if (!adapt_mesh(std::min(nominal_dt, loading.end_time)))
          break;
      solver::NewtonResult initial;
      initial.converged = true;
      history->add_row(history_row(initial, 0));
      write_output();
    }

    double       t_done = time;
    const double t_end = loading.end_time;
    const double start_fraction = t_done / t_end; // done before this process started
    // Small strain is meant for displacements small against the body: warn (once) otherwise.
    const auto box = GridTools::compute_bounding_box(triangulation).get_boundary_points();
    double     smallest_extent = std::numeric_limits<double>::max();
    for (unsigned int d = 0; d < dim; ++d)
      smallest_extent = std::min(smallest_extent, box.second[d] - box.first[d]);
    bool large_displacement_warned = !model->is_small_strain();
    while (t_done < t_end * (1. - 1e-12))
    {
      // Steps end on the grid of nominal steps (also after cutbacks and load-increment-ratio
      // sub-steps), so that outputs and histories of different runs share their times.
      const double next_grid
          = std::min(t_end, nominal_dt * (std::floor(t_done / nominal_dt + 1e-9) + 1.));
      double dt_try = std::min(dt, next_grid - t_done);
      if (t_end - (t_done + dt_try) < 1e-6 * nominal_dt)
        dt_try = t_end - t_done;

      unsigned int         cutbacks = 0;
      solver::NewtonResult result;
      const double         t_start = t_done;
      solve_step(t_start, dt_try, result, cutbacks);
      dt_try = time - t_start;
      const unsigned int status_changes = contact.active() ? contact.n_changed_statuses() : 0;

      commit_step();
      last_step_size = dt_try;
      ++step_number;
      t_done = time;
      const io::HistoryRow row = history_row(result, cutbacks);
      history->add_row(row);

      if (!large_displacement_warned && solution.linfty_norm() > 0.1 * smallest_extent)
      {
        large_displacement_warned = true;
        if (rank == 0)
          std::cerr << "ausroll: warning: step " << step_number << ": displacements of "
                    << solution.linfty_norm() << " mm exceed 10 % of the workpiece's smallest "
                    << "extent (" << smallest_extent << " mm) with Model/Kinematics = small "
                    << "strain; its results are not meaningful at this size: use a finite-strain "
                       "kinematics"
                    << std::endl;
      }
      const double       elapsed = wall_clock.wall_time();
      const double       fraction = t_done / t_end;
      std::ostringstream percent;
      percent << std::fixed << std::setprecision(1) << std::setw(5) << 100. * fraction;
      log << "step " << std::setw(4) << step_number << "  t = " << std::setw(9) << t_done << "  ("
          << percent.str() << "%)  Newton " << std::setw(2) << result.iterations;
      if (result.outer_passes > 0) // iterations summed over the passes (each within the maximum)
        log << " in " << result.outer_passes + 1 << " passes";
      log << "  cutbacks " << cutbacks;
      if (contact.active())
      {
        const auto [n_stick, n_slip] = contact.n_stick_slip();
        log << "  stick/slip " << n_stick << "/" << n_slip;
      }
      log << "  DoFs " << dof_handler.n_dofs() << "  elapsed " << format_seconds(elapsed)
          << "  ETA "
          << format_seconds(elapsed * (1. - fraction) / std::max(fraction - start_fraction, 1e-12))
          << std::endl;
      std::ostringstream line;
      line << "step " << step_number << std::setprecision(5);
      for (const auto &entry : row)
        if (entry.first != "wall_seconds" && entry.first != "step")
          line << " " << entry.first << "=" << (std::abs(entry.second) < 1e-12 ? 0. : entry.second);
      regression_log << line.str() << std::endl;

      check_distortion();

      if (parameters.adaptivity.interval > 0 && step_number % parameters.adaptivity.interval == 0
          && t_done < t_end * (1. - 1e-12))
        adapt_mesh(std::min(t_end, t_done + dt));

      const unsigned int interval = parameters.output.interval;
      if (interval > 0 && step_number % interval == 0)
        write_output();
      if (parameters.checkpoint.interval > 0 && step_number % parameters.checkpoint.interval == 0)
        write_checkpoint(dt);
      if (!resuming && parameters.checkpoint.abort_after_step == step_number)
      {
        log << "  aborting after step " << step_number << " (Checkpoint/Abort after step)"
            << std::endl;
        std::_Exit(99);
      }

      if (loading.step_control == solver::StepControl::adaptive)
      {
        // From the step actually taken after a cutback, else from the size asked for (a step
        // shortened to end on the nominal grid says nothing about the size that works).
        double factor = loading.step_factor(result.iterations, status_changes);
        if (cutbacks > 0)
          factor = std::min(factor, 1.);
        dt = std::min(nominal_dt, (cutbacks > 0 ? dt_try : dt) * factor);
        newton_log << "  step control: " << result.iterations << " Newton iterations, "
                   << status_changes << " contact status changes, " << cutbacks
                   << " cutbacks: next dt = " << dt << std::endl;
      }
      else
        dt = cutbacks > 0 ? dt_try : std::min(nominal_dt, dt * loading.step_growth_factor);
    }
    write_output();

    log << "finished: " << step_number << " steps in " << format_seconds(wall_clock.wall_time())
        << "; history: " << parameters.output.directory << "/history.csv";
    if (parameters.output.write_vtu)
      log << ", ParaView: " << parameters.output.directory << "/solution.pvd";
    log << std::endl;
    if (parameters.output.verbosity != io::Verbosity::regression
        && parameters.output.verbosity != io::Verbosity::quiet)
      timer->print_summary();
    regression_log << "finished: " << step_number << " steps" << std::endl;
  }

  void run_scene(const std::string                    &parameter_file,
                 const MPI_Comm                        comm,
                 const bool                            resume,
                 const std::vector<ParameterOverride> &overrides)
  {
    const SceneParameters     parameters = read_parameter_file(parameter_file, overrides);
    std::unique_ptr<Scene<2>> scene = std::make_unique<Scene<2>>(parameters, comm, resume);
    try
    {
      scene->run();
    }
    catch (...)
    {
      // Destroy the scene while the exception is handled (not in flight), so that its timers
      // and output close normally; then pass the error on.
      const std::exception_ptr error = std::current_exception();
      scene.reset();
      std::rethrow_exception(error);
    }
  }

  template class Scene<2>;
} // namespace ausroll::scene
