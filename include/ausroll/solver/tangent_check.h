/**
 * @file tangent_check.h
 * Finite-difference check of a Newton tangent along the Newton increment (a debug tool:
 * `AUSROLL_TANGENT_CHECK`, see NonlinearProblem::check_tangent()).
 */
#pragma once

#include <functional>
#include <vector>

namespace ausroll::solver
{
  /**
   * Errors of the linear model of a residual along a Newton increment d (K d = -r(u) with the
   * tangent K): e(eps) = |r(u + eps d) - (1 - eps) r(u)| / (eps |r(u)|) for each @p epsilons.
   * If K is the derivative of r, r(u + eps d) = (1 - eps) r(u) + O(eps^2) and e falls like eps;
   * an inconsistent tangent leaves the plateau e = |(K_true - K) d| / |r(u)|, the contraction
   * that Newton cannot beat (a linear rate). @p residual_at(eps) returns r(u + eps d), @p r0 is
   * r(u). VectorType needs copy, add(a, v) and l2_norm() (deal.II vectors).
   */
  template <typename VectorType>
  std::vector<double> linear_model_errors(const std::function<VectorType(double)> &residual_at,
                                          const VectorType                        &r0,
                                          const std::vector<double>               &epsilons)
  {
    std::vector<double> errors;
    const double        norm0 = r0.l2_norm();
    for (const double eps : epsilons)
    {
      VectorType difference = residual_at(eps);
      difference.add(-(1. - eps), r0);
      errors.push_back(difference.l2_norm() / (eps * norm0));
    }
    return errors;
  }
} // namespace ausroll::solver
