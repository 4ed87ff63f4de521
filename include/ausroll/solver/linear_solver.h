/**
 * @file linear_solver.h
 * Solution of the linearised equilibrium equations (`Solver/Linear solver`).
 */
#pragma once

#include <ausroll/core/exceptions.h>
#include <ausroll/solver/amg_reuse.h>
#include <ausroll/solver/solver_parameters.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <Amesos_BaseSolver.h>
#include <Epetra_CrsMatrix.h>
#include <Epetra_LinearProblem.h>

#include <memory>
#include <string>
#include <vector>

namespace ausroll::solver
{
  /** What one linear solve did. */
  /**
   * An iterative solve (`Solver/Linear solver/Type = iterative`, or `automatic` above its size
   * limit) that did not reach `Relative tolerance`: the Krylov method stopped at `Maximum
   * iterations`, or its true residual |b - A x| stayed above 100 x the tolerance. It is a
   * RunFailure (a run stops with it outside a Newton step), but NewtonSolver::solve() treats it as
   * a failed attempt of the step, as it treats a Newton iteration that does not converge: the
   * load stepper cuts the step back. A Krylov method that fails on one iterate often does so
   * because the iterate is bad (an element about to invert), which a shorter step avoids.
   */
  class IterativeSolveFailure : public RunFailure
  {
  public:
    using RunFailure::RunFailure;
  };

  struct LinearSolveInfo
  {
    unsigned int iterations = 0;     ///< Krylov iterations (0 for the direct solver)
    bool         iterative = false;  ///< the iterative solver was used (Type or automatic choice)
    double       setup_seconds = 0.; ///< wall time of the AMG set-up (0 for the direct solver)
    double       setup_cpu_seconds = 0.; ///< CPU time of the AMG set-up on this process
    double       seconds = 0.;           ///< wall time of set-up + solve
    double       cpu_seconds = 0.;       ///< CPU time of set-up + solve on this process
    bool         amg_setup = false; ///< the iterative solve set up a new AMG (false: a kept one)
    double       relative_tolerance = 0.; ///< the Krylov tolerance of the solve (iterative)
  };

  /**
   * How the automatic choices of `Solver/Linear solver` depend on the dimension of the mesh: the
   * fill-in of a sparse direct factorisation grows much faster in 3D (doc/benchmarks.md, "3D
   * linear solver": KLU equal to MUMPS at 2187 DoFs, 7x slower at 14739; in 2D equal near 10^4).
   */
  template <int dim>
  struct AutomaticSolverChoice;

  template <>
  struct AutomaticSolverChoice<2>
  {
    /** `Type = automatic` stays direct at any size. */
    static constexpr bool iterative_from_threshold = false;
    /** `Direct package = automatic` uses KLU (on one rank) below this many unknowns. */
    static constexpr dealii::types::global_dof_index klu_limit = 10000;
  };

  template <>
  struct AutomaticSolverChoice<3>
  {
    /** `Type = automatic` is iterative from `Automatic iterative threshold` unknowns on. */
    static constexpr bool iterative_from_threshold = true;
    /** `Direct package = automatic` uses KLU (on one rank) below this many unknowns. */
    static constexpr dealii::types::global_dof_index klu_limit = 3000;
  };

  /** The solver family that `Type = automatic` of @p parameters chooses for @p n_dofs unknowns
      (also for an estimate of them before the mesh exists). */
  template <int dim>
  LinearSolverType automatic_solver_type(const LinearSolverParameters &parameters,
                                         const double                  n_dofs);

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

    /** The rigid-body modes on the locally owned DoFs (3 in 2D, 6 in 3D), mode-major. */
    const std::vector<std::vector<double>> &get_rigid_body_modes() const
    {
      return rigid_body_modes;
    }

    /**
     * The matrix is about to be (re)initialised with a new sparsity pattern (call before every
     * reinit of the matrix, i.e. after every mesh change, while the old matrix still exists: the
     * kept solver refers to it): the direct solver's symbolic factorisation is redone at the next
     * solve. Between such calls the symbolic factorisation (ordering, elimination tree) is kept
     * and only the numeric one is redone for new matrix values; KLU then also keeps the pivot
     * order of its last pivoting factorisation and pivots again only when the residual of the
     * solve is not at round-off level (n_pivoting_refactorisations() counts those).
     */
    void matrix_pattern_changed();

    /** Solves whose kept KLU pivot order was rejected by the residual check (since construction).
     */
    unsigned int n_pivoting_refactorisations() const { return pivoting_refactorisations; }

    /**
     * The solver family used for a system of @p n_dofs unknowns: `Type`, or for Type = automatic
     * automatic_solver_type().
     */
    LinearSolverType resolved_type(dealii::types::global_dof_index n_dofs) const;

    /** Solve A x = b. Throws RunFailure if the solver fails. */
    LinearSolveInfo solve(const dealii::TrilinosWrappers::SparseMatrix &A,
                          dealii::TrilinosWrappers::MPI::Vector        &x,
                          const dealii::TrilinosWrappers::MPI::Vector  &b) const;

    /**
     * Solve A x = b; an iterative solve stops at |b - A x| <= @p relative_tolerance |b| (the
     * forcing term of inexact Newton, ForcingTerm) instead of `Relative tolerance`. The direct
     * solver ignores the tolerance.
     */
    LinearSolveInfo solve(const dealii::TrilinosWrappers::SparseMatrix &A,
                          dealii::TrilinosWrappers::MPI::Vector        &x,
                          const dealii::TrilinosWrappers::MPI::Vector  &b,
                          double                                        relative_tolerance) const;

    /** `Relative tolerance`: the Krylov tolerance of the overloads without one. */
    double default_relative_tolerance() const { return parameters.relative_tolerance; }

    /** AMG set-ups built so far (since construction; one per iterative solve without reuse). */
    unsigned int n_amg_setups() const { return amg_setups; }

    /**
     * Solve A x_k = b_k for several right-hand sides with one factorisation (direct) or one
     * AMG set-up (iterative; one Krylov solve each): the bordered system of generalized plane
     * strain. The iterations of the info are summed over the right-hand sides.
     */
    LinearSolveInfo
    solve(const dealii::TrilinosWrappers::SparseMatrix                     &A,
          const std::vector<dealii::TrilinosWrappers::MPI::Vector *>       &x,
          const std::vector<const dealii::TrilinosWrappers::MPI::Vector *> &b) const;

  private:
    using VectorList = std::vector<dealii::TrilinosWrappers::MPI::Vector *>;
    using ConstVectorList = std::vector<const dealii::TrilinosWrappers::MPI::Vector *>;

    /** Direct solve with a kept symbolic factorisation of @p A by Amesos package @p package:
        one numeric factorisation, a solve for each of @p b into @p x. */
    void solve_direct(const dealii::TrilinosWrappers::SparseMatrix &A,
                      const VectorList                             &x,
                      const ConstVectorList                        &b,
                      const std::string                            &package) const;

    /** The solve of every public overload, with the Krylov tolerance @p relative_tolerance. */
    LinearSolveInfo solve(const dealii::TrilinosWrappers::SparseMatrix &A,
                          const VectorList                             &x,
                          const ConstVectorList                        &b,
                          double                                        relative_tolerance) const;

    /** Iterative solve: GMRES or CG preconditioned by the AMG (kept or new, AmgReuse). */
    void solve_iterative(const dealii::TrilinosWrappers::SparseMatrix &A,
                         const VectorList                             &x,
                         const ConstVectorList                        &b,
                         double                                        relative_tolerance,
                         LinearSolveInfo                              &info) const;

    /** Set up a new AMG for @p A with the rigid-body modes. */
    void set_up_amg(const dealii::TrilinosWrappers::SparseMatrix &A) const;

    /** Let KLU refactorise with its last pivot order (Amesos "Refactorize"). */
    void set_pivot_reuse(bool reuse) const;

    LinearSolverParameters parameters;
    /** The direct solver refactorises with kept pivots (KLU), checked by the residual. */
    mutable bool         reuse_pivots = false;
    mutable unsigned int pivoting_refactorisations = 0;
    /** Residual of the kept-pivot check (a member: not allocated at every solve). */
    mutable dealii::TrilinosWrappers::MPI::Vector pivot_check_residual;
    /** Amesos problem and solver of the direct path, kept between solves with one pattern. */
    mutable std::unique_ptr<Epetra_LinearProblem> direct_problem;
    mutable std::unique_ptr<Amesos_BaseSolver>    direct_solver;
    /** What direct_solver was built for: matrix object and package (empty: nothing). */
    mutable const Epetra_CrsMatrix *factored_matrix = nullptr;
    mutable std::string             factored_package;
    /** Rigid-body modes on the locally owned DoFs, mode-major. */
    std::vector<std::vector<double>> rigid_body_modes;
    /** The AMG of the iterative path, kept between solves with `AMG reuse` (it refers to the
        matrix: dropped by matrix_pattern_changed()), the matrix it was built for, and the rule
        that decides when it is rebuilt. */
    mutable std::unique_ptr<dealii::TrilinosWrappers::PreconditionAMG> amg;
    mutable const Epetra_CrsMatrix                                    *amg_matrix = nullptr;
    mutable AmgReuse                                                   amg_reuse;
    mutable unsigned int                                               amg_setups = 0;
  };
} // namespace ausroll::solver
