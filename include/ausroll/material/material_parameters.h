/**
 * @file material_parameters.h
 * The `Material` subsection of a scene's .prm file.
 */
#pragma once

#include <ausroll/material/property_table.h>

#include <deal.II/base/parameter_handler.h>

#include <string>

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
   *
   * The moduli and the hardening parameters are PropertyTable values: a number, or (in thermal
   * scenes, `Thermal/Enabled = true`) a piecewise-linear table in temperature `T1: v1, T2: v2` or
   * `file: NAME.csv`. The material point evaluates them at its temperature (MaterialState::
   * temperature, the temperature field at the start of the step).
   */
  struct MaterialParameters
  {
    PropertyTable    youngs_modulus{210000.};                     ///< `Young's modulus` E(T)
    PropertyTable    poissons_ratio{0.3};                         ///< `Poisson's ratio` nu(T)
    YieldCriterion   yield_criterion = YieldCriterion::von_mises; ///< `Yield criterion`
    PropertyTable    yield_stress{240.}; ///< `Yield stress` sigma_0(T) (initial uniaxial)
    HardeningLawType hardening_law = HardeningLawType::linear; ///< `Hardening law`
    PropertyTable    hardening_modulus{0.};                    ///< `Hardening modulus` H'(T)
    PropertyTable    reference_plastic_strain{0.01};           ///< `Reference plastic strain` eps_0
    PropertyTable    hardening_exponent{0.2};                  ///< `Hardening exponent` n
    PropertyTable    kinematic_hardening_modulus{0.}; ///< `Kinematic hardening modulus` H_k

    /** Declare the entries of subsection `Material` (the caller enters no subsection). */
    static void declare_parameters(dealii::ParameterHandler &prm);

    /** Read subsection `Material`; throws InputError for out-of-range or inconsistent values.
        @p input_directory resolves the `file:` tables. */
    void parse_parameters(dealii::ParameterHandler &prm, const std::string &input_directory = "");

    /** The full path of the first entry given as a table in temperature, or "" if every
        property is a constant. */
    std::string first_temperature_dependent_entry() const;

    /** True if any property depends on temperature. */
    bool depends_on_temperature() const { return !first_temperature_dependent_entry().empty(); }
  };
} // namespace ausroll::material
