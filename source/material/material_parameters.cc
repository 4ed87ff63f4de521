#include <ausroll/core/exceptions.h>
#include <ausroll/material/material_parameters.h>

namespace ausroll::material
{
  using dealii::Patterns::Double;
  using dealii::Patterns::Selection;

  void MaterialParameters::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    prm.declare_entry("Young's modulus", "210000", Double(0.), "Young's modulus E (MPa).");
    prm.declare_entry(
        "Poisson's ratio", "0.3", Double(-1., 0.5), "Poisson's ratio nu (-1 < nu < 0.5).");
    prm.declare_entry("Yield criterion",
                      "von Mises",
                      Selection("none|von Mises"),
                      "Yield criterion: 'none' for a purely elastic material, 'von Mises' for J2 "
                      "plasticity with isotropic (and optional linear kinematic) hardening.");
    prm.declare_entry(
        "Yield stress", "240", Double(0.), "Initial uniaxial yield stress sigma_0 (MPa).");
    prm.declare_entry("Hardening law",
                      "linear",
                      Selection("linear|power law"),
                      "Isotropic hardening: 'linear' sigma_y = sigma_0 + H' eps_p; 'power law' "
                      "sigma_y = sigma_0 (1 + eps_p/eps_0)^n.");
    prm.declare_entry("Hardening modulus",
                      "0",
                      Double(0.),
                      "Slope H' of the linear hardening law (MPa); 0 = perfectly plastic.");
    prm.declare_entry("Reference plastic strain",
                      "0.01",
                      Double(0.),
                      "eps_0 of the power law (must be > 0 when the power law is used).");
    prm.declare_entry("Hardening exponent", "0.2", Double(0.), "Exponent n of the power law.");
    prm.declare_entry("Kinematic hardening modulus",
                      "0",
                      Double(0.),
                      "Linear (Prager) kinematic hardening modulus H_k (MPa); 0 = none.");
    prm.leave_subsection();
  }

  void MaterialParameters::parse_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    youngs_modulus = prm.get_double("Young's modulus");
    poissons_ratio = prm.get_double("Poisson's ratio");
    yield_criterion
        = prm.get("Yield criterion") == "none" ? YieldCriterion::none : YieldCriterion::von_mises;
    yield_stress = prm.get_double("Yield stress");
    hardening_law = prm.get("Hardening law") == "linear" ? HardeningLawType::linear
                                                         : HardeningLawType::power_law;
    hardening_modulus = prm.get_double("Hardening modulus");
    reference_plastic_strain = prm.get_double("Reference plastic strain");
    hardening_exponent = prm.get_double("Hardening exponent");
    kinematic_hardening_modulus = prm.get_double("Kinematic hardening modulus");
    prm.leave_subsection();

    require(youngs_modulus > 0., "Material/Young's modulus", "must be positive");
    require(poissons_ratio > -1. && poissons_ratio < 0.5,
            "Material/Poisson's ratio",
            "must lie in (-1, 0.5)");
    if (yield_criterion != YieldCriterion::none)
    {
      require(yield_stress > 0., "Material/Yield stress", "must be positive");
      if (hardening_law == HardeningLawType::power_law)
        require(reference_plastic_strain > 0.,
                "Material/Reference plastic strain",
                "must be positive for the power law");
    }
  }
} // namespace ausroll::material
