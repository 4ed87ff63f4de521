#include <ausroll/material/hardening_law.h>

#include <cmath>

namespace ausroll::material
{
  HardeningLaw::HardeningLaw(const MaterialParameters &parameters, const double temperature)
      : type(parameters.hardening_law)
      , sigma_0(parameters.yield_stress.value(temperature))
      , modulus(parameters.hardening_modulus.value(temperature))
      , eps_0(parameters.reference_plastic_strain.value(temperature))
      , exponent(parameters.hardening_exponent.value(temperature))
  {
  }

  double HardeningLaw::yield_stress(const double eq_plastic_strain) const
  {
    if (type == HardeningLawType::linear)
      return sigma_0 + modulus * eq_plastic_strain;
    return sigma_0 * std::pow(1. + eq_plastic_strain / eps_0, exponent);
  }

  double HardeningLaw::slope(const double eq_plastic_strain) const
  {
    if (type == HardeningLawType::linear)
      return modulus;
    return sigma_0 * exponent / eps_0 * std::pow(1. + eq_plastic_strain / eps_0, exponent - 1.);
  }
} // namespace ausroll::material
