#include <ausroll/solver/equilibrium_problem.h>

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
  {
  }

  template <int dim>
  bool EquilibriumProblem<dim>::assemble(const bool with_matrix, std::string &message)
  {
    TimerOutput::Scope scope(timer, "assembly");
    strategy.begin_iterate(time);
    // Statuses that the strategy changes at this iterate (judged by the reactions of this very
    // assembly) require the constraints to be rebuilt and the system re-assembled.
    for (;;)
    {
      strategy.update_geometry(system.solution_ghosted);
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
      const unsigned int changes = strategy.update_at_iterate();
      if (changes == 0)
        break;
      detail_log << "      contact: " << changes << " status change" << (changes > 1 ? "s" : "")
                 << ", re-assembling" << std::endl;
    }
    // 3D: the derivative of the slip direction of the slipping nodes (at this assembly's normal
    // forces)
    if constexpr (dim == 3)
      if (with_matrix && contact.active())
        contact.add_slip_direction_tangent(
            system.newton_constraints, system.system_matrix, system.rhs);
    // The curvature tangent is planar (2D only; Scene<3> leaves curvature_tangent null).
    if constexpr (dim == 2)
      if (with_matrix && contact.active() && curvature_tangent != nullptr)
        curvature_tangent->add_to(contact,
                                  system.newton_constraints,
                                  system.solution_ghosted,
                                  system.residual_ghosted,
                                  time,
                                  system.system_matrix);
    // Force level: external loads and reactions (residual at prescribed DoFs).
    last_residual_norm = system.free_residual.l2_norm();
    last_reference_force = std::max(system.external_force.l2_norm(), system.reaction_norm());
    return true;
  }

  template <int dim>
  LinearSolveInfo EquilibriumProblem<dim>::solve_for_increment()
  {
    TimerOutput::Scope scope(timer, "linear solve");
    system.newton_start = system.solution;
    system.increment = 0.;
    const LinearSolveInfo info
        = linear_solver.solve(system.system_matrix, system.increment, system.rhs);
    system.newton_constraints.distribute(system.increment);
    return info;
  }

  template class EquilibriumProblem<2>;
  template class EquilibriumProblem<3>;
} // namespace ausroll::solver
