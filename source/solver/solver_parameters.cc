#include <ausroll/core/exceptions.h>
#include <ausroll/solver/solver_parameters.h>

namespace ausroll::solver
{
  using namespace dealii;

  void SolverParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Solver");
    prm.declare_entry("Maximum Newton iterations",
                      "25",
                      Patterns::Integer(1, 1000),
                      "Newton iterations per load step before the step is cut back.");
    prm.declare_entry("Residual tolerance",
                      "1e-6",
                      Patterns::Double(0.),
                      "Convergence when the out-of-balance force of the free equations is below "
                      "this fraction of the force level (max of external forces and reactions). "
                      "With the same steps, 1e-6 and 1e-9 give answers within 6e-7 of each other "
                      "(disk rolling force; 1e-8 for the upsetting force and the gear flank), and "
                      "1e-6 saves one or two iterations per step; solve tighter only to compare "
                      "runs below 1e-6 (doc/scenes/hard_cases.md, section 12).");
    prm.declare_entry("Absolute residual tolerance",
                      "1e-10",
                      Patterns::Double(0.),
                      "Convergence when the out-of-balance force is below this value (N).");
    prm.declare_entry(
        "Divergence factor",
        "1e6",
        Patterns::Double(1.),
        "A step is abandoned when the residual exceeds this multiple of its first value.");
    prm.declare_entry(
        "Status pass tolerance",
        "1e-4",
        Patterns::Double(0., 1.),
        "Constraints that depend on the solution (the contact statuses of Contact/Strategy = "
        "nested active set) are judged at an iterate whose out-of-balance force is below this "
        "fraction of the force level (or at convergence, if Residual tolerance is looser). The "
        "statuses that no longer change are then converged to Residual tolerance, so the answer "
        "is a converged state with consistent statuses whatever the value; a looser value saves "
        "the last iterations of the intermediate passes, but statuses are judged on less accurate "
        "reactions and may take another path (doc/scenes/disk_rolling.md).");
    prm.declare_entry(
        "Status pass gap tolerance",
        "1e-10",
        Patterns::Double(0., 1.),
        "The status pass (Status pass tolerance) judges an iterate only if its largest constraint "
        "gap (e.g. the second-order gap d^2 / 2R that a curved die leaves after each iteration) "
        "is below this fraction of the smallest cell diameter. Convergence always requires "
        "1e-10, so the answer is a converged state with consistent statuses whatever the value; "
        "a looser value lets an intermediate pass end at the iterate where the residual is "
        "first below Status pass tolerance instead of one or two iterations later, when the gap "
        "has closed to round-off (doc/scenes/disk_rolling.md).");
    prm.declare_entry(
        "Line search",
        "true",
        Patterns::Bool(),
        "Backtracking line search: a step is accepted when the residual norm decreases or the "
        "energy criterion |d.r(eta)| <= 0.8 |d.r(0)| holds.");
    prm.enter_subsection("Linear solver");
    prm.declare_entry(
        "Type",
        "automatic",
        Patterns::Selection("automatic|direct|iterative"),
        "direct: sparse LU (Trilinos Amesos; the fastest for 2D up to 10^6 DoFs, see "
        "doc/benchmarks.md); iterative: Krylov method (Iterative method) + algebraic multigrid "
        "with the rigid-body modes; automatic: direct for every 2D system and for 3D systems "
        "with fewer unknowns than Automatic iterative threshold, iterative for larger 3D ones.");
    prm.declare_entry("Automatic iterative threshold",
                      "1e4",
                      Patterns::Double(0.),
                      "Type = automatic: 3D systems with at least this many unknowns are solved "
                      "iteratively (the measured cross-over of direct and AMG solves, "
                      "doc/benchmarks.md section 3D linear solver).");
    prm.declare_entry("Direct solver package",
                      "automatic",
                      Patterns::Selection("automatic|MUMPS|KLU"),
                      "Amesos package for Type = direct: automatic (KLU on one MPI rank below "
                      "10^4 unknowns in 2D and 3000 in 3D, MUMPS otherwise), MUMPS (runs in "
                      "parallel), KLU (serial).");
    prm.declare_entry("Iterative method",
                      "GMRES",
                      Patterns::Selection("GMRES|CG"),
                      "Krylov method for Type = iterative. CG needs a symmetric positive definite "
                      "tangent (small strain, associative plasticity, no friction or follower "
                      "pressure); GMRES works for any tangent.");
    prm.declare_entry("Relative tolerance",
                      "1e-10",
                      Patterns::Double(0.),
                      "Iterative solver tolerance: |b - A x| <= this times |b| (with Krylov "
                      "tolerance = adaptive the tightest tolerance of a solve).");
    prm.declare_entry(
        "Krylov tolerance",
        "adaptive",
        Patterns::Selection("fixed|adaptive"),
        "Tolerance of each iterative solve of a Newton iteration. fixed: Relative tolerance. "
        "adaptive (inexact Newton): the forcing term of Eisenstat and Walker (choice 2, "
        "gamma = 0.9, alpha = 2, with their safeguard and the end-game bound 0.5 x Newton "
        "tolerance / |r|) between Relative tolerance and Maximum forcing term: loose while the "
        "Newton residual is far from its tolerance, tight where Newton converges quadratically. "
        "The Newton test stays on the true residual, so the answer is converged to Residual "
        "tolerance either way (doc/studies/linear_solver_3d.md). The direct solver ignores it.");
    prm.declare_entry("Maximum forcing term",
                      "1e-4",
                      Patterns::Double(0., 1.),
                      "Krylov tolerance = adaptive: the loosest relative tolerance of a solve "
                      "(the first solve of a Newton step or of a status pass). 1e-4 keeps the "
                      "Newton iterations of the 3D gear and disk scenes (1e-2: up to 30 % more, "
                      "and more cutbacks; doc/studies/linear_solver_3d.md).");
    prm.declare_entry(
        "AMG reuse",
        "true",
        Patterns::Bool(),
        "Keep the AMG set-up of the iterative solver for the following solves (Newton "
        "iterations and steps) while the matrix pattern stays (no mesh change); it is rebuilt "
        "when a solve needs more than AMG rebuild factor times the Krylov iterations per decade "
        "of residual reduction of the first solve with it, and a solve that fails with a kept "
        "set-up is repeated with a new one (doc/studies/linear_solver_3d.md).");
    prm.declare_entry("AMG rebuild factor",
                      "1.5",
                      Patterns::Double(1.),
                      "AMG reuse = true: rebuild the AMG when a solve needs more than this many "
                      "times the Krylov iterations per decade of the first solve with it.");
    prm.declare_entry(
        "Maximum iterations", "2000", Patterns::Integer(1), "Iterative solver limit.");
    prm.declare_entry(
        "GMRES restart", "200", Patterns::Integer(1), "Krylov vectors kept by GMRES.");
    prm.declare_entry("AMG aggregation threshold",
                      "0.02",
                      Patterns::Double(0., 1.),
                      "ML aggregation threshold: matrix entries below this fraction of the "
                      "diagonal are dropped when the aggregates are built.");
    prm.declare_entry("AMG smoother sweeps",
                      "2",
                      Patterns::Integer(1, 20),
                      "Pre- and post-smoothing sweeps per multigrid level.");
    prm.declare_entry("AMG smoother",
                      "Chebyshev",
                      Patterns::Selection("Chebyshev|symmetric Gauss-Seidel|ILU"),
                      "ML smoother on each level.");
    prm.leave_subsection();
    prm.leave_subsection();
  }

  void SolverParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Solver");
    max_newton_iterations = prm.get_integer("Maximum Newton iterations");
    residual_tolerance = prm.get_double("Residual tolerance");
    absolute_tolerance = prm.get_double("Absolute residual tolerance");
    divergence_factor = prm.get_double("Divergence factor");
    status_pass_tolerance = prm.get_double("Status pass tolerance");
    status_pass_gap_tolerance = prm.get_double("Status pass gap tolerance");
    line_search = prm.get_bool("Line search");
    prm.enter_subsection("Linear solver");
    const std::string type = prm.get("Type");
    linear.type = type == "direct"      ? LinearSolverType::direct
                  : type == "iterative" ? LinearSolverType::iterative
                                        : LinearSolverType::automatic;
    linear.automatic_iterative_threshold = prm.get_double("Automatic iterative threshold");
    linear.direct_package = prm.get("Direct solver package");
    linear.krylov_method
        = prm.get("Iterative method") == "CG" ? KrylovMethod::cg : KrylovMethod::gmres;
    linear.relative_tolerance = prm.get_double("Relative tolerance");
    linear.krylov_tolerance = prm.get("Krylov tolerance") == "adaptive" ? KrylovTolerance::adaptive
                                                                        : KrylovTolerance::fixed;
    linear.maximum_forcing_term = prm.get_double("Maximum forcing term");
    linear.amg_reuse = prm.get_bool("AMG reuse");
    linear.amg_rebuild_factor = prm.get_double("AMG rebuild factor");
    linear.max_iterations = prm.get_integer("Maximum iterations");
    linear.restart = prm.get_integer("GMRES restart");
    linear.amg_aggregation_threshold = prm.get_double("AMG aggregation threshold");
    linear.amg_smoother_sweeps = prm.get_integer("AMG smoother sweeps");
    linear.amg_smoother_type = prm.get("AMG smoother");
    prm.leave_subsection();
    prm.leave_subsection();
    require(linear.relative_tolerance > 0. && linear.relative_tolerance < 1.,
            "Solver/Linear solver/Relative tolerance",
            "must lie in (0, 1)");
    require(linear.krylov_tolerance == KrylovTolerance::fixed
                || linear.maximum_forcing_term >= linear.relative_tolerance,
            "Solver/Linear solver/Maximum forcing term",
            "must not be smaller than Solver/Linear solver/Relative tolerance ("
                + std::to_string(linear.relative_tolerance) + ")");
    require(residual_tolerance > 0. || absolute_tolerance > 0.,
            "Solver/Residual tolerance",
            "either the relative or the absolute tolerance must be positive");
  }
} // namespace ausroll::solver
