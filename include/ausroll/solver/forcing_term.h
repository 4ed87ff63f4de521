/**
 * @file forcing_term.h
 * The relative tolerance of each Krylov solve of a Newton solve (`Solver/Linear solver/Krylov
 * tolerance`): fixed, or the forcing term of inexact Newton.
 */
#pragma once

#include <ausroll/solver/solver_parameters.h>

namespace ausroll::solver
{
  /**
   * Forcing term eta_k of inexact Newton: the linear solve of iteration k stops at
   * |b - A x| <= eta_k |b| instead of Relative tolerance. With Krylov tolerance = adaptive it is
   * choice 2 of Eisenstat and Walker (SIAM J. Sci. Comput. 17, 1996) with the safeguards of
   * Kelley (Iterative Methods for Linear and Nonlinear Equations, SIAM 1995, section 6.3):
   *
   *     eta_0 = eta_max  (the first solve of a Newton solve or of a status pass)
   *     A     = gamma (|r_k| / |r_k-1|)^2                         gamma = 0.9
   *     B     = max(A, gamma eta_k-1^2)  if gamma eta_k-1^2 > 0.1, else A
   *     eta_k = min(eta_max, max(B, 0.5 tol / |r_k|))
   *
   * bounded below by `Relative tolerance`; eta_max is `Maximum forcing term`, tol the Newton
   * tolerance of the iterate. The first rule follows the convergence of Newton itself (quadratic
   * convergence: |r_k| / |r_k-1| small, a tight solve; slow convergence: a loose one); the
   * safeguard keeps eta from falling by more than the square of its last value in one step; the
   * last term stops oversolving at the end: a linear residual of 0.5 tol is all the last iteration
   * needs. With Krylov tolerance = fixed next() always returns Relative tolerance.
   */
  class ForcingTerm
  {
  public:
    /** The rule of @p parameters (`Krylov tolerance`, `Relative tolerance`, `Maximum forcing
        term`). */
    explicit ForcingTerm(const LinearSolverParameters &parameters);

    /** A new Newton solve or status pass: the next tolerance is eta_max (no history). */
    void restart();

    /**
     * The relative tolerance of the linear solve at an iterate whose Newton residual norm is
     * @p residual_norm, with the Newton tolerance @p newton_tolerance (same unit); records
     * both for the next call.
     */
    double next(double residual_norm, double newton_tolerance);

    static constexpr double gamma = 0.9; ///< Eisenstat-Walker choice 2
    static constexpr double alpha = 2.;  ///< Eisenstat-Walker choice 2

  private:
    bool   adaptive;
    double minimum; ///< `Relative tolerance`
    double maximum; ///< `Maximum forcing term`
    double previous_norm = 0.;
    double previous_eta = 0.;
    bool   has_previous = false;
  };
} // namespace ausroll::solver
