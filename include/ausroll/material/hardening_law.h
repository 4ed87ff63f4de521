/**
 * @file hardening_law.h
 * Isotropic hardening laws sigma_y(eps_p).
 */
#pragma once

#include <ausroll/material/material_parameters.h>

namespace ausroll::material
{
  /**
   * Current uniaxial yield stress as a function of the equivalent plastic strain
   * (`Material/Hardening law`, `Yield stress`, `Hardening modulus`, `Reference plastic strain`,
   * `Hardening exponent`).
   */
  class HardeningLaw
  {
  public:
    /** The law selected in @p parameters, its parameters evaluated at @p temperature. */
    explicit HardeningLaw(const MaterialParameters &parameters, const double temperature = 0.);

    /** sigma_y(eps_p). */
    double yield_stress(const double eq_plastic_strain) const;

    /** d sigma_y / d eps_p. */
    double slope(const double eq_plastic_strain) const;

  private:
    HardeningLawType type;     ///< linear or power law
    double           sigma_0;  ///< initial yield stress
    double           modulus;  ///< H' of the linear law
    double           eps_0;    ///< reference strain of the power law
    double           exponent; ///< exponent of the power law
  };
} // namespace ausroll::material
