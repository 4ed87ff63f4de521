#include <ausroll/contact/friction/levanov.h>

#include <cmath>

namespace ausroll::contact
{
  using namespace dealii;

  LevanovFriction::LevanovFriction(const double m, const double k)
      : shear(m * k)
      , c(exponent_factor / (std::sqrt(3.) * k))
  {
  }

  double LevanovFriction::shear_stress(const double pressure) const
  {
    return shear * (1. - std::exp(-c * pressure));
  }

  SlipLimit LevanovFriction::slip_limit(const double normal_force, const double area) const
  {
    if (!(area > 0.))
      return SlipLimit();
    if (normal_force <= 0.)
      return {0., shear * c};
    const double decay = std::exp(-c * normal_force / area);
    const double slope = shear * c * decay;
    const double value = shear * area * (1. - decay);
    return {value - slope * normal_force, slope};
  }

} // namespace ausroll::contact

AUSROLL_REGISTER_FRICTION_LAW(ausroll::contact::LevanovParameters,
                              "Levanov",
                              "Levanov",
                              "pressure-dependent shear, |t_t| <= m k (1 - exp(-1.25 p / sigma_0)) "
                              "(Levanov/Friction factor m)")
