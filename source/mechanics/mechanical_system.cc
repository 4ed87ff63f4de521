#include <ausroll/mechanics/mechanical_system.h>

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <cmath>
#include <limits>

namespace ausroll::mechanics
{
  using namespace dealii;

  template <int dim>
  MechanicalSystem<dim>::MechanicalSystem(const MPI_Comm comm, const unsigned int degree)
      : comm(comm)
      , triangulation(comm,
                      typename Triangulation<dim>::MeshSmoothing(
                          Triangulation<dim>::smoothing_on_refinement
                          | Triangulation<dim>::smoothing_on_coarsening))
      , fe(FE_Q<dim>(degree), dim)
      , mapping(degree)
      , dof_handler(triangulation)
  {
  }

  template <int dim>
  void MechanicalSystem<dim>::setup_system()
  {
    ++assembly_cache.state;
    ++assembly_cache.pattern; // a new matrix below
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
    if (out_of_plane.active)
    {
      out_of_plane.column.reinit(owned_dofs, comm);
      out_of_plane.row.reinit(owned_dofs, comm);
    }

    double h_min = std::numeric_limits<double>::max();
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        h_min = std::min(h_min, cell->minimum_vertex_distance());
    min_cell_diameter = Utilities::MPI::min(h_min, comm);
  }

  template <int dim>
  double MechanicalSystem<dim>::smallest_extent() const
  {
    const auto box = GridTools::compute_bounding_box(triangulation).get_boundary_points();
    double     extent = std::numeric_limits<double>::max();
    for (unsigned int d = 0; d < dim; ++d)
      extent = std::min(extent, box.second[d] - box.first[d]);
    return extent;
  }

  template <int dim>
  void MechanicalSystem<dim>::initialize_material_points(const unsigned int points_per_cell)
  {
    ++assembly_cache.state;
    material_points.initialize(triangulation.begin_active(), triangulation.end(), points_per_cell);
  }

  template <int dim>
  double MechanicalSystem<dim>::build_newton_constraints(
      const BoundaryConditions<dim>                            &boundary_conditions,
      const double                                              time,
      const std::function<double(AffineConstraints<double> &)> &add_more)
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
    if (add_more)
      violation = std::max(violation, add_more(newton_constraints));
    newton_constraints.close();
    return Utilities::MPI::max(violation, comm);
  }

  template <int dim>
  void MechanicalSystem<dim>::start_step(const double predictor_ratio)
  {
    ++assembly_cache.state;
    solution = step_start;
    if (predictor_ratio != 0.)
    {
      // u_n + ratio (u_n - u_n-1)
      solution.add(predictor_ratio, step_start);
      solution.add(-predictor_ratio, previous_start);
    }
    solution_ghosted = solution;
    if (out_of_plane.active)
      out_of_plane.stretch
          = out_of_plane.step_start
            + predictor_ratio * (out_of_plane.step_start - out_of_plane.previous_start);
  }

  template <int dim>
  void MechanicalSystem<dim>::restore_step_start()
  {
    ++assembly_cache.state;
    solution = step_start;
    solution_ghosted = solution;
    out_of_plane.stretch = out_of_plane.step_start;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto &point : material_points.get_data(cell))
          point->reset_trial();
  }

  template <int dim>
  void MechanicalSystem<dim>::commit_step(const bool new_step)
  {
    ++assembly_cache.state;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto &point : material_points.get_data(cell))
          point->commit();
    if (new_step)
    {
      previous_start = step_start;
      out_of_plane.previous_start = out_of_plane.step_start;
    }
    step_start = solution;
    out_of_plane.step_start = out_of_plane.stretch;
  }

  template <int dim>
  AssemblyTargets MechanicalSystem<dim>::assembly_targets(const bool with_matrix)
  {
    residual = 0.;
    external_force = 0.;
    free_residual = 0.;
    AssemblyTargets targets;
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
    if (out_of_plane.active)
    {
      if (with_matrix)
      {
        out_of_plane.column = 0.;
        out_of_plane.row = 0.;
      }
      targets.out_of_plane = &out_of_plane;
    }
    return targets;
  }

  template <int dim>
  void MechanicalSystem<dim>::apply_increment(const double step_length)
  {
    solution = newton_start;
    solution.add(step_length, increment);
    solution_ghosted = solution;
    if (out_of_plane.active)
      out_of_plane.stretch = out_of_plane.newton_start + step_length * out_of_plane.increment;
  }

  template <int dim>
  double MechanicalSystem<dim>::reaction_norm() const
  {
    double reaction_sq = 0.;
    for (const auto i : owned_dofs)
      if (newton_constraints.is_constrained(i) && !hanging_constraints.is_constrained(i))
        reaction_sq += residual[i] * residual[i];
    return std::sqrt(Utilities::MPI::sum(reaction_sq, comm));
  }

  template <int dim>
  std::pair<unsigned int, unsigned int>
  MechanicalSystem<dim>::execute_refinement(const std::function<void()> &attach_data,
                                            const std::function<void()> &unpack_data)
  {
    parallel::distributed::SolutionTransfer<dim, Vector> transfer(dof_handler);
    // the converged solution before this one too: the predictor of the next step extrapolates
    // from both (setup_system() zeroes it)
    Vector previous_ghosted(owned_dofs, relevant_dofs, comm);
    previous_ghosted = previous_start;
    triangulation.prepare_coarsening_and_refinement();
    unsigned int n_refined = 0, n_coarsened = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
      {
        n_refined += cell->refine_flag_set() ? 1 : 0;
        n_coarsened += cell->coarsen_flag_set() ? 1 : 0;
      }
    n_refined = Utilities::MPI::sum(n_refined, comm);
    n_coarsened = Utilities::MPI::sum(n_coarsened, comm);
    transfer.prepare_for_coarsening_and_refinement(
        std::vector<const Vector *>{&solution_ghosted, &previous_ghosted});
    attach_data();
    triangulation.execute_coarsening_and_refinement();
    ++assembly_cache.state;

    setup_system();
    unpack_data();
    Vector                interpolated(owned_dofs, comm);
    Vector                previous_interpolated(owned_dofs, comm);
    std::vector<Vector *> targets{&interpolated, &previous_interpolated};
    transfer.interpolate(targets);
    hanging_constraints.distribute(interpolated);
    hanging_constraints.distribute(previous_interpolated);
    solution = interpolated;
    solution_ghosted = solution;
    step_start = solution;
    previous_start = previous_interpolated;
    return {n_refined, n_coarsened};
  }

  template <int dim>
  void MechanicalSystem<dim>::rebase_material_points(const Assembler<dim>              &assembler,
                                                     const material::ConstitutiveModel &model)
  {
    ++assembly_cache.state;
    // with the deformation gradient the material sees (F-bar included): re-basing with the plain
    // F left every F-bar state off equilibrium by the difference, growing at every adaptation
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
      {
        const std::vector<Tensor<2, 3>> F
            = assembler.material_deformation_gradients(cell, solution_ghosted);
        const auto points = material_points.get_data(cell);
        for (unsigned int q = 0; q < points.size(); ++q)
        {
          model.rebase(points[q]->committed, F[q]);
          points[q]->trial = points[q]->committed;
        }
      }
  }

  template class MechanicalSystem<2>;
  template class MechanicalSystem<3>;
} // namespace ausroll::mechanics
