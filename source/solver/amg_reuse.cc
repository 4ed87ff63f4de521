#include <ausroll/solver/amg_reuse.h>

#include <cmath>

namespace ausroll::solver
{
  AmgReuse::AmgReuse(const bool reuse, const double rebuild_factor)
      : reuse(reuse)
      , rebuild_factor(rebuild_factor)
  {
  }

  void AmgReuse::set_up()
  {
    valid = true;
    reference = 0.;
  }

  double AmgReuse::iterations_per_decade(const unsigned int iterations, const double reduction)
  {
    if (iterations == 0 || !(reduction > 0.) || !(reduction < 1.))
      return 0.;
    return iterations / -std::log10(reduction);
  }

  void AmgReuse::solved(const unsigned int iterations, const double reduction)
  {
    const double rate = iterations_per_decade(iterations, reduction);
    if (rate == 0. || iterations < minimum_judged_iterations)
      return;
    if (reference == 0.)
      reference = rate;
    else if (rate > rebuild_factor * reference)
      valid = false;
  }
} // namespace ausroll::solver
