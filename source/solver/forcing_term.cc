#include <ausroll/solver/forcing_term.h>

#include <algorithm>
#include <cmath>

namespace ausroll::solver
{
  ForcingTerm::ForcingTerm(const LinearSolverParameters &parameters)
      : adaptive(parameters.krylov_tolerance == KrylovTolerance::adaptive)
      , minimum(parameters.relative_tolerance)
      , maximum(std::max(parameters.maximum_forcing_term, parameters.relative_tolerance))
  {
  }

  void ForcingTerm::restart()
  {
    has_previous = false;
  }

  double ForcingTerm::next(const double residual_norm, const double newton_tolerance)
  {
    if (!adaptive)
      return minimum;
    double eta = maximum;
    // (a zero residual before: the first iterate of a step that only had to meet constraints)
    if (has_previous && previous_norm > 0. && std::isfinite(residual_norm))
    {
      eta = gamma * std::pow(residual_norm / previous_norm, alpha);
      const double safeguard = gamma * std::pow(previous_eta, alpha);
      if (safeguard > 0.1)
        eta = std::max(eta, safeguard);
      if (residual_norm > 0.)
        eta = std::max(eta, 0.5 * newton_tolerance / residual_norm);
      eta = std::min(eta, maximum);
    }
    eta = std::max(eta, minimum);
    previous_norm = residual_norm;
    previous_eta = eta;
    has_previous = true;
    return eta;
  }
} // namespace ausroll::solver
