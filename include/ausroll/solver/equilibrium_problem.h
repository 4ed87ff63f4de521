/**
 * @file equilibrium_problem.h
 * The nonlinear system of a load step as the Newton solver sees it: equilibrium of the
 * MechanicalSystem under the boundary conditions and the contact constraints of the contact
 * strategy.
 */
#pragma once

#include <ausroll/contact/contact_operator.h>
#include <ausroll/contact/contact_strategy.h>
#include <ausroll/mechanics/assembler.h>
#include <ausroll/mechanics/boundary_conditions.h>
#include <ausroll/mechanics/mechanical_system.h>
#include <ausroll/solver/linear_solver.h>
#include <ausroll/solver/newton_solver.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <algorithm>

namespace ausroll::solver
{
  /**
   * solver::NonlinearProblem on a MechanicalSystem: assemble() projects the contact nodes (as the
   * contact strategy says), builds the Newton constraints (hanging nodes, Dirichlet increments,
   * contact), assembles with the Assembler and lets the strategy judge the statuses by the
   * reactions (re-assembling while it changes some); solve_for_increment() uses the LinearSolver.
   * The force level is max(|f_ext|, |reactions at prescribed DoFs|), but at least 1e-3 of the
   * largest level of the converged states so far (below it forces are round-off noise, e.g. a
   * die just lifting off: the residual need not be smaller than the run's round-off).
   * All referenced objects must outlive the problem.
   */
  template <int dim>
  class EquilibriumProblem : public NonlinearProblem
  {
  public:
    /** The problem at the pseudo-time @p time (the owner's clock; read at every assembly). */
    EquilibriumProblem(mechanics::MechanicalSystem<dim>         &system,
                       const mechanics::Assembler<dim>          &assembler,
                       const mechanics::BoundaryConditions<dim> &boundary_conditions,
                       contact::ContactOperator<dim>            &contact,
                       contact::StatusStrategy                  &strategy,
                       LinearSolver<dim>                        &linear_solver,
                       const double                             &time,
                       dealii::TimerOutput                      &timer,
                       dealii::ConditionalOStream               &detail_log);

    bool   assemble(const bool with_matrix, std::string &message) override;
    double residual_norm() const override { return last_residual_norm; }
    double reference_force() const override
    {
      return std::max(last_reference_force, 1e-3 * largest_reference_force);
    }
    double constraint_violation() const override { return last_constraint_violation; }
    void   set_linear_tolerance(const double relative_tolerance) override
    {
      linear_tolerance = relative_tolerance;
    }
    LinearSolveInfo solve_for_increment() override;
    void apply_increment(const double step_length) override { system.apply_increment(step_length); }
    double length_scale() const override { return system.min_cell_diameter; }
    double increment_residual_product() const override
    {
      const double product = system.increment * system.free_residual;
      // generalized plane strain: + dlambda r_lambda (r_lambda = dPi/dlambda)
      return system.out_of_plane.active
                 ? product + system.out_of_plane.increment * system.out_of_plane.residual()
                 : product;
    }
    /** The contact strategy's update of the statuses at a converged state (nested active set):
        the reactions of the last assembly decide. */
    unsigned int update_constraints_at_convergence(dealii::ConditionalOStream &log) override
    {
      return strategy.update_at_convergence(system.solution_ghosted, log);
    }
    /** As the contact strategy says (nested active set: curved dies leave second-order gaps). */
    bool backtrack_with_small_constraint_gaps() const override
    {
      return strategy.backtrack_with_small_constraint_gaps();
    }

    /**
     * Finite-difference check of the tangent along the last increment d: for eps = 1e-2 ... 1e-6
     * prints e(eps) = |r(u + eps d) - (1 - eps) r(u)| / (eps |r(u)|) over the free equations
     * (falls like eps for a consistent tangent, stays for an inconsistent one), where the largest
     * difference sits, and how many quadrature points are plastic at u and at u + d and switch
     * between them. The contact statuses of u are kept for all these evaluations (the strategy is
     * not asked), so the Newton path is that without the check. Leaves the iterate and its
     * assembly as at u (re-assembled).
     */
    void check_tangent(dealii::ConditionalOStream &log) override;

    /** The last assembly was of a converged state: its force level counts for the run's. */
    void commit()
    {
      largest_reference_force = std::max(largest_reference_force, last_reference_force);
    }

    double largest_reference_force = 0.; ///< largest force level of the converged states so far

  private:
    mechanics::MechanicalSystem<dim>         &system;
    const mechanics::Assembler<dim>          &assembler;
    const mechanics::BoundaryConditions<dim> &boundary_conditions;
    contact::ContactOperator<dim>            &contact;
    contact::StatusStrategy                  &strategy;
    LinearSolver<dim>                        &linear_solver;
    const double                             &time;
    dealii::TimerOutput                      &timer;
    dealii::ConditionalOStream               &detail_log;

    /** Krylov tolerance of the next solve_for_increment() (set_linear_tolerance(); initially
        `Relative tolerance`). */
    double linear_tolerance;
    double last_residual_norm = 0.;
    double last_reference_force = 0.;
    double last_constraint_violation = 0.;
    /** check_tangent() at work: assemble with the contact statuses of the iterate (projections
        updated, no closing, no judging by the strategy). */
    bool fixed_statuses = false;
  };
} // namespace ausroll::solver
