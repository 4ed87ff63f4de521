#include <ausroll/core/exceptions.h>
#include <ausroll/solver/forcing_term.h>
#include <ausroll/solver/newton_solver.h>

#include <cmath>
#include <cstdlib>
#include <ctime>
#include <iomanip>
#include <limits>
#include <sstream>

namespace ausroll::solver
{
  NewtonSolver::NewtonSolver(const SolverParameters &parameters)
      : parameters(parameters)
  {
  }

  AssemblyCount &AssemblyCount::operator+=(const AssemblyCount &other)
  {
    first += other.first;
    after_solve += other.after_solve;
    line_search += other.line_search;
    status_pass += other.status_pass;
    for (unsigned int k = 0; k < cpu_seconds.size(); ++k)
      cpu_seconds[k] += other.cpu_seconds[k];
    return *this;
  }

  namespace
  {
    /** CPU seconds of this process (all its threads). */
    double process_cpu_seconds()
    {
      return static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
    }
  } // namespace

  NewtonResult NewtonSolver::solve(NonlinearProblem &problem, dealii::ConditionalOStream &log) const
  {
    NewtonResult result;
    // every return adds this solve's assemblies to the solver's totals
    struct AddOnReturn
    {
      AssemblyCount       &total;
      const AssemblyCount &mine;
      ~AddOnReturn() { total += mine; }
    } add_on_return{assemblies, result.assemblies};
    std::string message;
    // one assembly of kind k (AssemblyCount: first, after a solve, line-search trial, status pass)
    const auto assemble = [&](const unsigned int k)
    {
      const double start = process_cpu_seconds();
      const bool   ok = problem.assemble(true, message);
      result.assemblies.cpu_seconds[k] += process_cpu_seconds() - start;
      return ok;
    };
    const double constraint_tolerance = 1e-10 * problem.length_scale();
    // debug tool (doc/scenes/hard_cases.md section 9): finite-difference check of the tangent
    static const bool tangent_check = std::getenv("AUSROLL_TANGENT_CHECK") != nullptr;

    ++result.assemblies.first;
    if (!assemble(0))
    {
      result.reason = message;
      return result;
    }
    double first_norm = problem.residual_norm();
    double previous_norm = std::numeric_limits<double>::infinity();
    // Outer passes of a problem that updates its constraints at convergence: each pass gets the
    // full Newton budget; more passes than this means the constraints cycle.
    constexpr unsigned int max_outer_passes = 30;
    unsigned int           pass_start = 0;
    // Residuals relative to the force level at each iterate ('|' marks a new status pass): the
    // summary line at convergence says where the solves of the step went.
    std::ostringstream history;
    unsigned int       line_searches = 0;
    // the Krylov tolerance of each linear solve (fixed, or inexact Newton); the test below stays
    // on the true residual of every iterate
    ForcingTerm forcing_term(parameters.linear);

    for (unsigned int it = 0;; ++it)
    {
      double       norm = problem.residual_norm();
      const double reference = problem.reference_force();
      const double tolerance
          = std::max(parameters.absolute_tolerance, parameters.residual_tolerance * reference);
      bool constraints_ok = problem.constraint_violation() <= constraint_tolerance;
      result.residual = norm;

      log << "    Newton " << std::setw(2) << it << ": |r| = " << std::scientific
          << std::setprecision(3) << norm << "  (tol " << tolerance << ")";
      if (!constraints_ok)
        log << "  constraint gap " << problem.constraint_violation();
      log << std::defaultfloat << std::endl;

      if (log.is_active())
        history << (it > 0 ? " " : "") << std::scientific << std::setprecision(1)
                << norm / std::max(reference, std::numeric_limits<double>::min());
      if (!std::isfinite(norm))
      {
        result.reason = "residual is not a finite number";
        return result;
      }
      bool converged
          = norm <= tolerance && constraints_ok && (it > 0 || norm == 0. || reference > 0.);
      // Round-off floor: the residual no longer decreases although it is already tiny compared
      // with the force level (ill-conditioned systems, e.g. a body held by one contact node).
      if (!converged && it >= pass_start + 2 && constraints_ok && norm <= 1e-6 * reference
          && norm > 0.5 * previous_norm)
      {
        log << "    (residual at round-off level, accepted)" << std::endl;
        converged = true;
      }
      // Constraints that depend on the solution (nested active set) are updated once the
      // reactions are accurate to `Status pass tolerance` (1e-4) of the force level: the last
      // quadratic iterations of an intermediate pass would not change the statuses.
      // A constraint gap below `Status pass gap tolerance` does not change the statuses either.
      const bool nearly_converged
          = problem.constraint_violation() <= std::max(
                constraint_tolerance, parameters.status_pass_gap_tolerance * problem.length_scale())
            && norm <= std::max(tolerance, parameters.status_pass_tolerance * reference)
            && it > pass_start;
      unsigned int changes = 0;
      if (converged || nearly_converged)
      {
        changes = problem.update_constraints_at_convergence(log);
        if (changes == 0 && converged)
        {
          log << "    Newton summary: " << result.iterations << " solves, " << result.outer_passes
              << " status passes, " << line_searches
              << " line searches; |r| / force level:" << (history.str().empty() ? "" : " ")
              << history.str() << std::endl;
          result.converged = true;
          return result;
        }
      }
      if (changes > 0)
      {
        if (++result.outer_passes > max_outer_passes)
        {
          std::ostringstream msg;
          msg << "the contact statuses still change after " << max_outer_passes
              << " converged passes";
          result.reason = msg.str();
          return result;
        }
        ++result.assemblies.status_pass;
        if (!assemble(3))
        {
          result.reason = message;
          return result;
        }
        pass_start = it;
        norm = problem.residual_norm();
        constraints_ok = problem.constraint_violation() <= constraint_tolerance;
        first_norm = norm;
        previous_norm = std::numeric_limits<double>::infinity();
        forcing_term.restart(); // new constraints: the residual history starts again
        log << "    Newton " << std::setw(2) << it << ": |r| = " << std::scientific
            << std::setprecision(3) << norm << "  (" << changes << " contact status change"
            << (changes > 1 ? "s" : "") << ")";
        if (!constraints_ok)
          log << "  constraint gap " << problem.constraint_violation();
        log << std::defaultfloat << std::endl;
        if (log.is_active())
          history << " |" << std::scientific << std::setprecision(1)
                  << norm / std::max(problem.reference_force(), std::numeric_limits<double>::min());
        // fall through: iterate with the new constraints
      }
      else
        previous_norm = norm;
      if (it >= pass_start + parameters.max_newton_iterations)
      {
        std::ostringstream msg;
        msg << "no convergence in " << parameters.max_newton_iterations
            << " Newton iterations (|r| = " << norm << ", tolerance " << tolerance << ")";
        result.reason = msg.str();
        return result;
      }
      if (it > pass_start + 1
          && norm > parameters.divergence_factor * std::max(first_norm, tolerance))
      {
        result.reason = "Newton iteration diverges";
        return result;
      }

      // Backtracking also when the constraints are nearly met at this iterate: the linearised
      // contact constraint on a curved die leaves a gap of second order (d^2 / 2R) after each
      // iteration.
      const bool nearly_met = problem.backtrack_with_small_constraint_gaps()
                              && problem.constraint_violation() <= std::max(
                                     constraint_tolerance, 1e-3 * problem.length_scale());
      LinearSolveInfo info;
      problem.set_linear_tolerance(forcing_term.next(norm, tolerance));
      try
      {
        info = problem.solve_for_increment();
      }
      catch (const IterativeSolveFailure &e)
      {
        // a failed attempt like a Newton iteration that does not converge: the step is cut back
        result.reason = e.what();
        return result;
      }
      result.linear_iterations += info.iterations;
      log << "    linear solve: " << info.iterations << " iterations, " << std::fixed
          << std::setprecision(3) << info.seconds << " s wall, " << info.cpu_seconds << " s CPU";
      if (info.iterative)
      {
        if (info.amg_setup)
          log << " (AMG set-up " << info.setup_cpu_seconds << " s CPU";
        else
          log << " (AMG kept";
        log << ", tolerance " << std::scientific << std::setprecision(1) << info.relative_tolerance
            << ")";
      }
      log << std::defaultfloat << std::endl;
      ++result.iterations;
      if (tangent_check)
        problem.check_tangent(log);
      // directional derivative of the energy along the increment at the start of the step
      const double slope = problem.increment_residual_product();

      // Full step first; backtrack only when the previous iterate satisfied the constraints
      // (a step that imposes new prescribed displacements legitimately raises the residual).
      double step = 1.;
      problem.apply_increment(step);
      ++result.assemblies.after_solve;
      bool admissible = assemble(1);
      if (parameters.line_search && (constraints_ok || (nearly_met && it > pass_start)))
        for (unsigned int ls = 0; ls < 6; ++ls)
        {
          if (admissible && problem.residual_norm() <= (1. - 1e-4 * step) * norm)
            break;
          if (admissible && slope < 0.
              && std::abs(problem.increment_residual_product()) <= 0.8 * std::abs(slope)
              && std::isfinite(problem.residual_norm()))
            break;
          log << "      eta " << step << ": " << (admissible ? "" : "inadmissible, ")
              << "|r| = " << problem.residual_norm() << ", d.r ratio "
              << problem.increment_residual_product() / slope << std::endl;
          step *= 0.5;
          problem.apply_increment(step);
          ++result.assemblies.line_search;
          admissible = assemble(2);
        }
      else if (parameters.line_search)
        // New constraints (moved dies, prescribed displacements): the residual may rise, but an
        // inadmissible state (inverted element, failed return map) is never accepted; shorten
        // the step instead of giving the whole load step up. The constraints not yet met are
        // imposed again by the next iteration.
        for (unsigned int ls = 0; ls < 6 && !admissible; ++ls)
        {
          step *= 0.5;
          problem.apply_increment(step);
          ++result.assemblies.line_search;
          admissible = assemble(2);
        }
      if (step < 1.)
      {
        ++line_searches;
        log << "    line search: step length " << step << std::endl;
      }
      if (!admissible)
      {
        result.reason = message;
        return result;
      }
      if (it == pass_start)
        first_norm = std::max(first_norm, problem.residual_norm());
    }
  }
} // namespace ausroll::solver
