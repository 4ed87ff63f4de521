/**
 * @file linear_solver.h
 * Solution of the linearised equilibrium equations (`Solver/Linear solver`).
 */
#pragma once

#include <ausroll/solver/solver_parameters.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>
#include <vector>

namespace ausroll::solver
{
  /** What one linear solve did. */
  struct LinearSolveInfo
  {
    unsigned int iterations = 0;   ///< Krylov iterations (0 for the direct solver)
    double       seconds = 0.;     ///< wall time of set-up + solve
    double       cpu_seconds = 0.; ///< CPU time of set-up + solve on this process
  };

  /**
   * Direct (Amesos MUMPS/KLU) or iterative (GMRES or CG + ML algebraic multigrid) solver. The AMG
   * preconditioner is given the rigid-body modes of the displacement field (translations and
   * rotations) as near null space, which deal.II 9.4 does not provide by itself.
   */
  template <int dim>
  class LinearSolver
  {
  public:
    /** Solver configured by subsection `Solver/Linear solver`. */
    explicit LinearSolver(const LinearSolverParameters &parameters);

    /** Record the rigid-body modes of @p dof_handler (call after every mesh change). */
    void set_rigid_body_modes(const dealii::DoFHandler<dim> &dof_handler,
                              const dealii::Mapping<dim>    &mapping);

    /** Solve A x = b. Throws RunFailure if the solver fails. */
    LinearSolveInfo solve(const dealii::TrilinosWrappers::SparseMatrix &A,
                          dealii::TrilinosWrappers::MPI::Vector        &x,
                          const dealii::TrilinosWrappers::MPI::Vector  &b) const;

  private:
    LinearSolverParameters parameters;
    /** Rigid-body modes on the locally owned DoFs, mode-major. */
    std::vector<std::vector<double>> rigid_body_modes;
  };
} // namespace ausroll::solver
