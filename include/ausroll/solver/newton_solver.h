/**
 * @file newton_solver.h
 * Newton-Raphson iteration of one load step with line search and divergence detection.
 */
#pragma once

#include <ausroll/solver/linear_solver.h>
#include <ausroll/solver/solver_parameters.h>

#include <deal.II/base/conditional_ostream.h>

#include <array>
#include <string>

namespace ausroll::solver
{
  /**
   * The nonlinear system of one load step, as the Newton solver sees it. The implementation
   * (the scene) owns the iterate u, the constraints and the matrices.
   */
  class NonlinearProblem
  {
  public:
    virtual ~NonlinearProblem() = default;

    /**
     * Rebuild the constraints of the Newton increment at the current iterate and evaluate the
     * residual (and, with @p with_matrix, the tangent and right-hand side). Returns false and sets
     * @p message if the state is not admissible (inverted element, failed material update).
     */
    virtual bool assemble(const bool with_matrix, std::string &message) = 0;

    /** Norm of the out-of-balance force of the free equations at the last assembly. */
    virtual double residual_norm() const = 0;

    /** Force level the residual is compared with (external loads, reactions). */
    virtual double reference_force() const = 0;

    /** Largest violation of the prescribed displacement / contact constraints at the last assembly.
     */
    virtual double constraint_violation() const = 0;

    /**
     * The relative tolerance of the iterative linear solves that follow (the forcing term of
     * inexact Newton, `Solver/Linear solver/Krylov tolerance`; NewtonSolver sets it before every
     * solve_for_increment()). A problem that solves directly or exactly ignores it (the default).
     */
    virtual void set_linear_tolerance(const double relative_tolerance) { (void)relative_tolerance; }

    /** Solve the linearised system for the increment (uses the last assembled matrix). */
    virtual LinearSolveInfo solve_for_increment() = 0;

    /** Set the iterate to u_start + @p step_length * increment, u_start being the iterate at the
        last solve_for_increment(). */
    virtual void apply_increment(const double step_length) = 0;

    /** Length scale for the constraint tolerance (e.g. the mesh size), in mm. */
    virtual double length_scale() const = 0;

    /**
     * The product d . r of the last increment d (solve_for_increment()) with the out-of-balance
     * force of the free equations r at the last assembly: the directional derivative of the
     * potential energy along d (negative at the start of a descent step, zero at its minimum).
     */
    virtual double increment_residual_product() const = 0;

    /**
     * Called when the iteration has converged with the current constraints, or nearly (residual
     * below 1e-4 of the force level, constraints met). A problem whose constraints depend on the
     * converged state (contact statuses of the nested active set) updates them and returns the
     * number of changes; the solver then re-assembles and continues (a new outer pass). The
     * default changes nothing.
     */
    virtual unsigned int update_constraints_at_convergence(dealii::ConditionalOStream &log)
    {
      (void)log;
      return 0;
    }

    /**
     * Whether the line search may backtrack while the constraints are only nearly met (violation
     * below 1e-3 of the length scale: the second-order gap d^2 / 2R a linearised contact
     * constraint on a curved die leaves after each iteration). Default: backtrack only once the
     * constraints are met.
     */
    virtual bool backtrack_with_small_constraint_gaps() const { return false; }

    /**
     * Debug check of the tangent along the last increment d (environment variable
     * `AUSROLL_TANGENT_CHECK` set: called after every solve_for_increment()). A problem that can
     * prints how far its residual r(u + eps d) is from the linear model (1 - eps) r(u) and leaves
     * the iterate u and its assembly as they were. The default prints nothing.
     */
    virtual void check_tangent(dealii::ConditionalOStream &log) { (void)log; }
  };

  /**
   * The assemblies (NonlinearProblem::assemble() calls) of Newton solves by what asked for them
   * (issue 38, doc/studies/newton_economy.md): they add up to the calls of the timer's "assembly"
   * section, except those of the `AUSROLL_TANGENT_CHECK` debug check.
   */
  struct AssemblyCount
  {
    unsigned long long first = 0;       ///< at the start of a solve (the step's first iterate)
    unsigned long long after_solve = 0; ///< at the full step after each linear solve
    unsigned long long line_search = 0; ///< at shortened steps (line-search trials, eta < 1)
    unsigned long long status_pass = 0; ///< after status changes at a converged state (same u)
    /** CPU seconds of the process in these four kinds of assemblies, in this order */
    std::array<double, 4> cpu_seconds{{0., 0., 0., 0.}};

    unsigned long long total() const { return first + after_solve + line_search + status_pass; }
    AssemblyCount     &operator+=(const AssemblyCount &other);
  };

  /** Outcome of one Newton solve. */
  struct NewtonResult
  {
    bool          converged = false;     ///< equilibrium reached
    unsigned int  iterations = 0;        ///< Newton iterations (linear solves)
    unsigned int  outer_passes = 0;      ///< constraint updates at convergence (nested active set)
    unsigned int  linear_iterations = 0; ///< Krylov iterations summed over the step
    double        residual = 0.;         ///< final residual norm
    std::string   reason;                ///< why it failed
    AssemblyCount assemblies;            ///< the assemblies of this solve
  };

  /**
   * Newton-Raphson with a backtracking line search (`Solver/Line search`), convergence test
   * |r_free| <= max(absolute tolerance, residual tolerance * force level) with satisfied
   * constraints, and detection of divergence, NaN and inadmissible states.
   *
   * Line search: a step length eta (1, 1/2, 1/4, ...) is accepted when the state is admissible
   * and either the residual norm decreases (|r(eta)| <= (1 - 1e-4 eta) |r(0)|) or the energy
   * criterion of Matthies and Strang / Crisfield holds, |d . r(eta)| <= 0.8 |d . r(0)| with
   * d . r(0) < 0. The second criterion lets Newton take the full step where the residual norm
   * rises temporarily although the step is good, as in slender structures whose first iterate
   * carries large spurious membrane forces (the cantilever: the residual grows by 60 after the
   * first iteration, the next iteration converges). While the constraints are not yet satisfied
   * (the first iteration of a step with moved dies or prescribed displacements) the residual may
   * rise and only inadmissible states (inverted elements, failed material updates) are backtracked.
   */
  class NewtonSolver
  {
  public:
    /** Solver configured by subsection `Solver`. */
    explicit NewtonSolver(const SolverParameters &parameters);

    /** Iterate @p problem to equilibrium; progress lines go to @p log (one per iteration). */
    NewtonResult solve(NonlinearProblem &problem, dealii::ConditionalOStream &log) const;

    /** The assemblies of all solve() calls so far (converged or not). */
    const AssemblyCount &assembly_count() const { return assemblies; }

  private:
    SolverParameters      parameters;
    mutable AssemblyCount assemblies;
  };
} // namespace ausroll::solver
