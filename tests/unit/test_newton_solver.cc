/**
 * Newton solver with constraints that are updated at converged states (the mechanism behind
 * `Contact/Strategy = nested active set`), on a one-unknown model of a node against a stop:
 * r(u) = u^3 + u - f while the node is free, u = g while it rests on the stop (u <= g). The stop
 * closes when a converged free state passes it, and opens when the reaction at a converged closed
 * state is tensile: at u = g the residual r is the force the stop exerts; r < 0 pushes the node
 * back (compression), r > 0 would pull it (tension). The exact answers are u = root of
 * u^3 + u = f (free) or u = g (closed).
 */
#include <ausroll/solver/newton_solver.h>

#include <deal.II/base/conditional_ostream.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

namespace
{
  using namespace ausroll::solver;

  class StopProblem : public NonlinearProblem
  {
  public:
    StopProblem(const double f, const double g, const bool closed)
        : f(f)
        , g(g)
        , closed(closed)
    {
    }

    bool assemble(const bool, std::string &) override
    {
      ++assemblies;
      residual = u * u * u + u - f;
      jacobian = 3. * u * u + 1.;
      return true;
    }
    double          residual_norm() const override { return closed ? 0. : std::abs(residual); }
    double          reference_force() const override { return std::abs(f); }
    double          constraint_violation() const override { return closed ? std::abs(u - g) : 0.; }
    LinearSolveInfo solve_for_increment() override
    {
      start = u;
      increment = closed ? g - u : -residual / jacobian;
      return {};
    }
    void   apply_increment(const double step) override { u = start + step * increment; }
    double length_scale() const override { return 1.; }
    double increment_residual_product() const override
    {
      return closed ? 0. : increment * residual;
    }
    unsigned int update_constraints_at_convergence(dealii::ConditionalOStream &) override
    {
      if (updates == 0)
        first_update_residual = std::abs(residual);
      ++updates;
      if (always_change)
        return 1;
      if (!closed && u > g)
      {
        closed = true; // passed the stop: close
        return 1;
      }
      if (closed && residual > 0.)
      {
        closed = false; // the stop would have to pull: open
        return 1;
      }
      return 0;
    }

    double       f, g;
    bool         closed;
    bool         always_change = false;
    double       u = 0., start = 0., increment = 0., residual = 0., jacobian = 1.;
    unsigned int assemblies = 0, updates = 0;
    double       first_update_residual = -1.; ///< |r| at the first judgement of the constraint
  };

  SolverParameters parameters()
  {
    SolverParameters p;
    p.residual_tolerance = 1e-12;
    p.absolute_tolerance = 1e-14;
    return p;
  }

  /** Solve @p problem with the tight tolerances above, silently. */
  NewtonResult solve(StopProblem &problem)
  {
    dealii::ConditionalOStream log(std::cout, false);
    return NewtonSolver(parameters()).solve(problem, log);
  }

  /** Root of u^3 + u = f by bisection (independent of Newton). */
  double free_solution(const double f)
  {
    double a = -10., b = 10.;
    for (unsigned int k = 0; k < 200; ++k)
    {
      const double m = 0.5 * (a + b);
      (m * m * m + m - f > 0. ? b : a) = m;
    }
    return 0.5 * (a + b);
  }
} // namespace

// No constraint change: converged in the first pass, quadratically (u^3 + u = 10 from u = 0 takes
// 6-8 iterations with line search; 12 would mean linear convergence).
TEST(NewtonSolver, FixedConstraintsConvergeInOnePass)
{
  StopProblem        problem(10., 100., false);
  const NewtonResult result = solve(problem);
  ASSERT_TRUE(result.converged) << result.reason;
  EXPECT_EQ(result.outer_passes, 0u);
  EXPECT_LE(result.iterations, 10u);
  EXPECT_NEAR(problem.u, free_solution(10.), 1e-12);
}

// The free solution (u = 2 for f = 10) passes the stop g = 1.5: the converged free state closes
// the node, Newton continues with u = g, the reaction r = g^3 + g - f = -5.125 is compressive,
// nothing changes: one outer pass, answer u = g exactly.
TEST(NewtonSolver, ConstraintClosedAtConvergedStateThenConverges)
{
  StopProblem        problem(10., 1.5, false);
  const NewtonResult result = solve(problem);
  ASSERT_TRUE(result.converged) << result.reason;
  EXPECT_EQ(result.outer_passes, 1u);
  EXPECT_TRUE(problem.closed);
  EXPECT_NEAR(problem.u, 1.5, 1e-14);
  EXPECT_NEAR(problem.residual, -5.125, 1e-12); // the stop pushes back
}

// Starting closed on a stop that would have to pull (f = 10, g = 3: r = 27 + 3 - 10 = 20 > 0,
// tension): the converged closed state opens the node, Newton finds the free root u = 2 < g, which
// stays open: one outer pass.
TEST(NewtonSolver, ConstraintOpenedAtConvergedState)
{
  StopProblem        problem(10., 3., true);
  const NewtonResult result = solve(problem);
  ASSERT_TRUE(result.converged) << result.reason;
  EXPECT_EQ(result.outer_passes, 1u);
  EXPECT_FALSE(problem.closed);
  EXPECT_NEAR(problem.u, free_solution(10.), 1e-12);
}

// The assemblies of a solve by kind (AssemblyCount, the run's "assemblies:" summary line): the
// problem counts its own assemble() calls. u^3 + u = 10 from u = 0 backtracks in its first
// iteration (the full step u = 10 gives r = 1000, u = 5 still 120, u = 2.5 is accepted), then
// closes on the stop g = 1.5 at the converged free state: one assembly at the start, one after
// each linear solve, one after the status change, the rest are line-search trials; the solver's
// totals add the solves up, CPU seconds included.
TEST(NewtonSolver, AssemblyCountAccountsForEveryAssembly)
{
  dealii::ConditionalOStream log(std::cout, false);
  const NewtonSolver         solver(parameters());
  AssemblyCount              sum;
  unsigned int               assemblies = 0;
  for (const double g : {1.5, 100.})
  {
    StopProblem        problem(10., g, false);
    const NewtonResult result = solver.solve(problem, log);
    ASSERT_TRUE(result.converged) << result.reason;
    const AssemblyCount &a = result.assemblies;
    EXPECT_EQ(a.total(), problem.assemblies);
    EXPECT_EQ(a.first, 1u);
    EXPECT_EQ(a.after_solve, result.iterations);
    EXPECT_EQ(a.status_pass, result.outer_passes);
    EXPECT_GE(a.line_search, 2u); // u = 10 and u = 5 rejected
    for (const double seconds : a.cpu_seconds)
      EXPECT_GE(seconds, 0.);
    sum += a;
    assemblies += problem.assemblies;
  }
  const AssemblyCount &total = solver.assembly_count();
  EXPECT_EQ(total.total(), assemblies);
  EXPECT_EQ(total.first, sum.first);
  EXPECT_EQ(total.after_solve, sum.after_solve);
  EXPECT_EQ(total.line_search, sum.line_search);
  EXPECT_EQ(total.status_pass, 1u); // the stop at 1.5 closes, the one at 100 is never reached
  for (unsigned int k = 0; k < total.cpu_seconds.size(); ++k)
    EXPECT_DOUBLE_EQ(total.cpu_seconds[k], sum.cpu_seconds[k]);
}

// Constraints that change at every converged state: the solver reports non-convergence after 30
// passes instead of looping for ever (the load step is then cut back).
TEST(NewtonSolver, CyclingConstraintsStopAfterThirtyPasses)
{
  StopProblem problem(10., 100., false);
  problem.always_change = true;
  const NewtonResult result = solve(problem);
  EXPECT_FALSE(result.converged);
  EXPECT_NE(result.reason.find("still change after 30"), std::string::npos) << result.reason;
  EXPECT_EQ(result.outer_passes, 31u);
}

// Statuses are judged before full convergence (residual below 1e-4 of the force level): the
// update is called at least once before the final, tight convergence, and the answer is still
// exact.
TEST(NewtonSolver, ConstraintsJudgedBeforeFullConvergence)
{
  StopProblem        problem(10., 100., false);
  const NewtonResult result = solve(problem);
  ASSERT_TRUE(result.converged);
  EXPECT_GE(problem.updates, 2u); // near convergence and at convergence
  EXPECT_NEAR(problem.u, free_solution(10.), 1e-12);
}

// `Solver/Status pass tolerance`: the constraint is judged once |r| <= tolerance * force level.
// With 0.1 the free pass (f = 10, stop g = 1.5 passed by the free root u = 2) is cut off at an
// iterate with |r| <= 1 (not converged: above 1e-4 * 10), with the default only below 1e-3; the
// closed state and its reaction are the same exact answer either way (u = g, r = -5.125), since
// the last pass is converged to the residual tolerance with the final constraint.
TEST(NewtonSolver, StatusPassToleranceJudgesConstraintsEarlierWithTheSameAnswer)
{
  dealii::ConditionalOStream log(std::cout, false);
  SolverParameters           loose = parameters();
  loose.status_pass_tolerance = 0.1;
  StopProblem        early(10., 1.5, false);
  const NewtonResult early_result = NewtonSolver(loose).solve(early, log);
  StopProblem        tight(10., 1.5, false);
  const NewtonResult tight_result = solve(tight);
  ASSERT_TRUE(early_result.converged) << early_result.reason;
  ASSERT_TRUE(tight_result.converged) << tight_result.reason;
  EXPECT_LE(early.first_update_residual, 0.1 * 10.);
  EXPECT_GT(early.first_update_residual, 1e-4 * 10.);
  EXPECT_LE(tight.first_update_residual, 1e-4 * 10.);
  EXPECT_LT(early_result.iterations, tight_result.iterations);
  EXPECT_EQ(early_result.outer_passes, 1u);
  EXPECT_TRUE(early.closed);
  EXPECT_NEAR(early.u, 1.5, 1e-14);
  EXPECT_NEAR(early.residual, -5.125, 1e-12);
}

namespace
{
  /**
   * The stop problem with a second constraint gap that closes only geometrically, by a factor of
   * 10 per Newton iteration whatever the residual (as the second-order gap d^2 / 2R a curved die
   * leaves after each iteration closes with the slip increments): it starts at 0.1 and is below
   * the convergence limit 1e-10 (length scale 1) only from the tenth iterate on, long after the
   * free residual of f = 10 is below 0.1 of the force level.
   */
  class GapProblem : public StopProblem
  {
  public:
    using StopProblem::StopProblem;
    double constraint_violation() const override
    {
      return std::max(StopProblem::constraint_violation(), gap);
    }
    LinearSolveInfo solve_for_increment() override
    {
      next_gap = 0.1 * gap;
      return StopProblem::solve_for_increment();
    }
    void apply_increment(const double step) override
    {
      StopProblem::apply_increment(step);
      gap = next_gap;
    }
    unsigned int update_constraints_at_convergence(dealii::ConditionalOStream &log) override
    {
      if (updates == 0)
        first_update_gap = gap;
      return StopProblem::update_constraints_at_convergence(log);
    }

    double gap = 0.1, next_gap = 0.1;
    double first_update_gap = -1.; ///< the gap at the first judgement of the stop
  };
} // namespace

// `Solver/Status pass gap tolerance`: with the default (1e-10, the convergence limit of the
// constraints) the stop is judged only once the gap has closed, at the tenth iterate although |r|
// is below Status pass tolerance (0.1 of f) long before; with 1e-3 it is judged at an iterate
// whose gap is still open (between 1e-10 and 1e-3). The last pass still converges the gap to
// 1e-10, so both find the exact closed state (u = g, reaction -5.125), the looser one in fewer
// iterations.
TEST(NewtonSolver, StatusPassGapToleranceJudgesAtOpenGapsWithTheSameAnswer)
{
  dealii::ConditionalOStream log(std::cout, false);
  SolverParameters           tight = parameters();
  tight.status_pass_tolerance = 0.1;
  SolverParameters loose = tight;
  loose.status_pass_gap_tolerance = 1e-3;
  GapProblem         early(10., 1.5, false);
  const NewtonResult early_result = NewtonSolver(loose).solve(early, log);
  GapProblem         late(10., 1.5, false);
  const NewtonResult late_result = NewtonSolver(tight).solve(late, log);
  ASSERT_TRUE(early_result.converged) << early_result.reason;
  ASSERT_TRUE(late_result.converged) << late_result.reason;
  EXPECT_LE(late.first_update_gap, 1e-10);
  EXPECT_GT(early.first_update_gap, 1e-10);
  EXPECT_LE(early.first_update_gap, 1e-3);
  EXPECT_LE(early.first_update_residual, 0.1 * 10.);
  EXPECT_LT(early_result.iterations, late_result.iterations);
  for (const GapProblem *p : {&early, &late})
  {
    EXPECT_TRUE(p->closed);
    EXPECT_LE(p->gap, 1e-10); // converged constraints
    EXPECT_NEAR(p->u, 1.5, 1e-14);
    EXPECT_NEAR(p->residual, -5.125, 1e-12);
  }
}

namespace
{
  /** The stop problem whose linear solve fails (as an iterative solve that does not converge)
      at the second iteration. */
  class FailingSolveProblem : public StopProblem
  {
  public:
    using StopProblem::StopProblem;
    LinearSolveInfo solve_for_increment() override
    {
      if (++solves == 2)
        throw IterativeSolveFailure("linear solver failed: the iterative solve did not converge");
      return StopProblem::solve_for_increment();
    }
    unsigned int solves = 0;
  };
} // namespace

// An iterative linear solve that fails inside a Newton step ends that attempt like a Newton
// iteration that does not converge (not converged, with the solver's message as the reason), so
// that the load stepper cuts the step back instead of ending the run; the solve is counted only
// when it succeeded. Any other RunFailure still passes through.
TEST(NewtonSolver, IterativeSolveFailureIsAFailedAttemptNotAnError)
{
  FailingSolveProblem problem(10., 100., false);
  NewtonResult        result;
  ASSERT_NO_THROW(result = solve(problem));
  EXPECT_FALSE(result.converged);
  EXPECT_NE(result.reason.find("iterative solve did not converge"), std::string::npos)
      << result.reason;
  EXPECT_EQ(result.iterations, 1u);
  EXPECT_EQ(problem.solves, 2u);
}
