/**
 * @file material_parameters.h
 * The `Material` subsection of a scene's .prm file.
 */
#pragma once

#include <deal.II/base/parameter_handler.h>

namespace ausroll::material
{
  /** Yield criterion of the workpiece material (`set Yield criterion`). */
  enum class YieldCriterion
  {
    none,     ///< purely elastic material
    von_mises ///< von Mises (J2) with isotropic and linear kinematic hardening
  };

  /** Isotropic hardening law sigma_y(eps_p) (`set Hardening law`). */
  enum class HardeningLawType
  {
    linear,   ///< sigma_y = sigma_0 + H' eps_p
    power_law ///< sigma_y = sigma_0 (1 + eps_p / eps_0)^n
  };

  /**
   * Parameters of subsection `Material`: isotropic elasticity and rate-independent plasticity.
   */
  struct MaterialParameters
  {
    double         youngs_modulus = 210000.;                    ///< `Young's modulus` E
    double         poissons_ratio = 0.3;                        ///< `Poisson's ratio` nu
    YieldCriterion yield_criterion = YieldCriterion::von_mises; ///< `Yield criterion`
    double         yield_stress = 240.; ///< `Yield stress` sigma_0 (initial uniaxial yield stress)
    HardeningLawType hardening_law = HardeningLawType::linear; ///< `Hardening law`
    double           hardening_modulus = 0.; ///< `Hardening modulus` H' of the linear law
    double reference_plastic_strain = 0.01;  ///< `Reference plastic strain` eps_0 of the power law
    double hardening_exponent = 0.2;         ///< `Hardening exponent` n of the power law
    double kinematic_hardening_modulus = 0.; ///< `Kinematic hardening modulus` H_k (Prager)

    /** Declare the entries of subsection `Material` (the caller enters no subsection). */
    static void declare_parameters(dealii::ParameterHandler &prm);
    /** Read subsection `Material`; throws InputError for out-of-range or inconsistent values. */
    void parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace ausroll::material
