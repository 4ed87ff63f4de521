#include <ausroll/solver/equilibrium_problem.h>
#include <ausroll/solver/out_of_plane_solve.h>
#include <ausroll/solver/tangent_check.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/vector.h>

#include <cmath>
#include <functional>
#include <iomanip>
#include <map>
#include <vector>

namespace ausroll::solver
{
  using namespace dealii;

  template <int dim>
  EquilibriumProblem<dim>::EquilibriumProblem(
      mechanics::MechanicalSystem<dim>         &system,
      const mechanics::Assembler<dim>          &assembler,
      const mechanics::BoundaryConditions<dim> &boundary_conditions,
      contact::ContactOperator<dim>            &contact,
      contact::StatusStrategy                  &strategy,
      LinearSolver<dim>                        &linear_solver,
      const double                             &time,
      TimerOutput                              &timer,
      ConditionalOStream                       &detail_log)
      : system(system)
      , assembler(assembler)
      , boundary_conditions(boundary_conditions)
      , contact(contact)
      , strategy(strategy)
      , linear_solver(linear_solver)
      , time(time)
      , timer(timer)
      , detail_log(detail_log)
      , linear_tolerance(linear_solver.default_relative_tolerance())
  {
  }

  template <int dim>
  bool EquilibriumProblem<dim>::assemble(const bool with_matrix, std::string &message)
  {
    TimerOutput::Scope scope(timer, "assembly");
    // check_tangent() evaluates with the statuses of the iterate: the strategy is not asked
    if (!fixed_statuses)
      strategy.begin_iterate(time);
    else if (contact.active())
      contact.set_time(time);
    // Statuses that the strategy changes at this iterate (judged by the reactions of this very
    // assembly) require the constraints to be rebuilt and the system re-assembled.
    for (;;)
    {
      if (!fixed_statuses)
        strategy.update_geometry(system.solution_ghosted);
      else if (contact.active())
        contact.update_geometry(system.solution_ghosted, false);
      last_constraint_violation = system.build_newton_constraints(
          boundary_conditions,
          time,
          [this](AffineConstraints<double> &constraints) {
            return contact.active() ? contact.add_constraints(system.solution_ghosted, constraints)
                                    : 0.;
          });
      const mechanics::AssemblyStatus status
          = assembler.assemble(system.dof_handler,
                               system.solution_ghosted,
                               time,
                               system.material_points,
                               system.hanging_constraints,
                               system.newton_constraints,
                               contact.active() ? &contact.row_transforms() : nullptr,
                               system.assembly_targets(with_matrix),
                               &system.assembly_cache);
      if (!status.ok)
      {
        message = status.message;
        return false;
      }
      if (!contact.active())
        break;
      system.residual_ghosted = system.residual;
      contact.compute_reactions(system.residual_ghosted);
      if (fixed_statuses)
        break;
      const unsigned int changes = strategy.update_at_iterate();
      if (changes == 0)
        break;
      detail_log << "      contact: " << changes << " status change" << (changes > 1 ? "s" : "")
                 << ", re-assembling" << std::endl;
    }
    // The contact Newton terms beyond the assembled tangent (slip direction, curvature), at this
    // assembly's reactions
    if (with_matrix && contact.active())
    {
      const contact::ContactTangentInput<dim> input{contact,
                                                    system.newton_constraints,
                                                    system.solution_ghosted,
                                                    system.residual_ghosted,
                                                    time};
      for (const auto &term : contact.tangent_terms())
        term->add_to(input, system.system_matrix, system.rhs);
    }
    // Force level: external loads and reactions (residual at prescribed DoFs).
    last_residual_norm = system.free_residual.l2_norm();
    last_reference_force = std::max(system.external_force.l2_norm(), system.reaction_norm());
    if (system.out_of_plane.active)
    {
      // generalized plane strain: the axial equation as a force on the section, N - N_target
      last_residual_norm = std::hypot(last_residual_norm, system.out_of_plane.force_error());
      last_reference_force = std::max(last_reference_force, std::abs(system.out_of_plane.target));
    }
    return true;
  }

  template <int dim>
  LinearSolveInfo EquilibriumProblem<dim>::solve_for_increment()
  {
    TimerOutput::Scope scope(timer, "linear solve");
    system.newton_start = system.solution;
    if (system.out_of_plane.active)
      return solve_out_of_plane_increment(linear_solver, system);
    system.increment = 0.;
    const LinearSolveInfo info
        = linear_solver.solve(system.system_matrix, system.increment, system.rhs, linear_tolerance);
    system.newton_constraints.distribute(system.increment);
    return info;
  }

  template <int dim>
  void EquilibriumProblem<dim>::check_tangent(ConditionalOStream &log)
  {
    // which quadrature points are plastic (their equivalent plastic strain grows in this step)
    const auto plastic_flags = [this]()
    {
      std::vector<char> flags;
      for (const auto &cell : system.triangulation.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto &point : system.material_points.get_data(cell))
            flags.push_back(point->trial.equivalent_plastic_strain
                            > point->committed.equivalent_plastic_strain);
      return flags;
    };
    const std::vector<char> plastic_at_u = plastic_flags();
    // the statuses of the iterate stay (the tangent is that of fixed statuses; a strategy that
    // judged them at u + eps d would also change the Newton path)
    fixed_statuses = true;
    using Vector = typename mechanics::MechanicalSystem<dim>::Vector;
    const Vector r0 = system.free_residual;
    const double norm0 = r0.l2_norm();
    const double axial0 = system.out_of_plane.residual(); // generalized plane strain
    std::string  message;
    log << "    tangent check: |r(u)| = " << std::scientific << std::setprecision(3) << norm0
        << ", e(eps) =";
    bool                                admissible = true;
    const std::function<Vector(double)> residual_at = [&](const double eps)
    {
      system.apply_increment(eps);
      admissible = assemble(false, message) && admissible;
      return system.free_residual;
    };
    const std::vector<double> epsilons{1e-2, 1e-3, 1e-4, 1e-5, 1e-6};
    for (const double e : linear_model_errors(residual_at, r0, epsilons))
      log << " " << std::setprecision(2) << e;
    if (system.out_of_plane.active && axial0 != 0.)
    {
      // the axial row k_eu . du + k_ee dlambda = -r_lambda of generalized plane strain
      dealii::Vector<double> a0(1);
      a0[0] = axial0;
      const std::function<dealii::Vector<double>(double)> axial_at = [&](const double eps)
      {
        system.apply_increment(eps);
        admissible = assemble(false, message) && admissible;
        dealii::Vector<double> a(1);
        a[0] = system.out_of_plane.residual();
        return a;
      };
      log << "; axial row e(eps) =";
      for (const double e : linear_model_errors(axial_at, a0, epsilons))
        log << " " << std::setprecision(2) << e;
    }
    if (!admissible)
      log << " (an inadmissible state on the way)";
    // where the largest difference sits (at eps = 1e-4)
    Vector difference = residual_at(1e-4);
    difference.add(-(1. - 1e-4), r0);
    types::global_dof_index worst = 0;
    double                  largest = -1.;
    for (const auto i : system.owned_dofs)
      if (std::abs(difference[i]) > largest)
      {
        largest = std::abs(difference[i]);
        worst = i;
      }
    std::map<types::global_dof_index, Point<dim>> support_points;
    DoFTools::map_dofs_to_support_points(system.mapping, system.dof_handler, support_points);
    if (support_points.count(worst) > 0)
      log << " [largest at dof " << worst << " (" << support_points[worst]
          << "): " << largest / (1e-4 * norm0) << "]";
    system.apply_increment(1.);
    const bool              full_ok = assemble(false, message);
    const std::vector<char> plastic_at_full = plastic_flags();
    unsigned int            n_u = 0, n_full = 0, switched = 0;
    for (unsigned int q = 0; q < plastic_at_u.size(); ++q)
    {
      n_u += plastic_at_u[q];
      n_full += plastic_at_full[q];
      switched += plastic_at_u[q] != plastic_at_full[q];
    }
    log << "; |r(u + d)| / |r(u)| = " << (full_ok ? system.free_residual.l2_norm() / norm0 : -1.)
        << "; plastic points " << n_u << " -> " << n_full << ", " << switched << " switch"
        << std::defaultfloat << std::endl;
    system.apply_increment(0.);
    assemble(true, message);
    fixed_statuses = false;
  }

  template class EquilibriumProblem<2>;
  template class EquilibriumProblem<3>;
} // namespace ausroll::solver
