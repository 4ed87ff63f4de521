/**
 * @file solver_parameters.h
 * The `Solver` subsection: Newton iteration and linear solver.
 */
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace ausroll::solver
{
  /** Linear solver family (`Solver/Linear solver/Type`). */
  enum class LinearSolverType
  {
    automatic, ///< direct in 2D and for 3D systems below `Automatic iterative threshold`
               ///< unknowns, iterative from there on (LinearSolver::resolved_type())
    direct,    ///< sparse direct factorisation (Trilinos Amesos: MUMPS or KLU)
    iterative ///< Krylov method preconditioned by algebraic multigrid (Trilinos ML) with rigid-body
              ///< modes
  };

  /** Krylov method of the iterative solver (`Solver/Linear solver/Iterative method`). */
  enum class KrylovMethod
  {
    gmres, ///< restarted GMRES: any matrix (friction, follower loads, F-bar, finite strain)
    cg     ///< conjugate gradients: only for symmetric positive definite tangents
  };

  /** Tolerance rule of the iterative solver (`Solver/Linear solver/Krylov tolerance`). */
  enum class KrylovTolerance
  {
    fixed,   ///< every solve to `Relative tolerance` of its right-hand side
    adaptive ///< inexact Newton: the forcing term of ForcingTerm (Eisenstat-Walker, choice 2)
  };

  /** Parameters of subsection `Solver/Linear solver`. */
  struct LinearSolverParameters
  {
    LinearSolverType type = LinearSolverType::automatic; ///< `Type`
    /** `Automatic iterative threshold`: Type = automatic solves 3D systems with at least this
        many unknowns iteratively (measured cross-over: doc/benchmarks.md, "3D linear solver"). */
    double      automatic_iterative_threshold = 1e4;
    std::string direct_package = "automatic"; ///< `Direct solver package` (automatic | MUMPS | KLU)
    KrylovMethod    krylov_method = KrylovMethod::gmres; ///< `Iterative method` (GMRES | CG)
    double          relative_tolerance = 1e-10; ///< `Relative tolerance` of the iterative solver
    KrylovTolerance krylov_tolerance = KrylovTolerance::adaptive; ///< `Krylov tolerance`
    /** `Maximum forcing term`: the loosest relative tolerance of Krylov tolerance = adaptive */
    double maximum_forcing_term = 1e-4;
    /** `AMG reuse`: keep the AMG set-up over the solves of one matrix pattern (LinearSolver) */
    bool amg_reuse = true;
    /** `AMG rebuild factor`: a kept AMG is rebuilt when a solve needs more than this many
        times the Krylov iterations per decade of its first solve */
    double       amg_rebuild_factor = 1.5;
    unsigned int max_iterations = 2000;            ///< `Maximum iterations` of the iterative solver
    unsigned int restart = 200;                    ///< `GMRES restart`
    double       amg_aggregation_threshold = 0.02; ///< `AMG aggregation threshold` (ML)
    unsigned int amg_smoother_sweeps = 2;          ///< `AMG smoother sweeps` (ML)
    std::string  amg_smoother_type = "Chebyshev";  ///< `AMG smoother` (ML smoother type)
  };

  /** Parameters of subsection `Solver`. */
  struct SolverParameters
  {
    unsigned int max_newton_iterations = 25; ///< `Maximum Newton iterations`
    double       residual_tolerance = 1e-6;  ///< `Residual tolerance` (relative to the force level)
    double       absolute_tolerance = 1e-10; ///< `Absolute residual tolerance` (N)
    double       divergence_factor = 1e6;    ///< `Divergence factor`: abort when |r| grows by it
    /** `Status pass tolerance`: constraints that depend on the solution (nested active set) are
        judged once |r| is below this fraction of the force level (or converged). */
    double status_pass_tolerance = 1e-4;
    /** `Status pass gap tolerance`: the largest constraint gap (relative to the smallest cell
        diameter) of an iterate that the status pass may judge; convergence still needs 1e-10. */
    double                 status_pass_gap_tolerance = 1e-10;
    bool                   line_search = true; ///< `Line search`
    LinearSolverParameters linear;             ///< subsection `Linear solver`

    /** Declare subsection `Solver`. */
    static void declare_parameters(dealii::ParameterHandler &prm);
    /** Read subsection `Solver`. */
    void parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace ausroll::solver
