#include <ausroll/core/exceptions.h>
#include <ausroll/material/material_parameters.h>

namespace ausroll::material
{
  using dealii::Patterns::Selection;

  namespace
  {
    /** How a property entry is written (appended to each entry's documentation). */
    const std::string table_note
        = " A number, or in thermal scenes a table in temperature 'T1: v1, T2: v2, ...' "
          "(linear between rows, constant beyond the first and the last) or 'file: NAME.csv' "
          "(two columns: temperature, value; NAME relative to the .prm file).";

    /** The entries that hold properties, with their defaults and documentation. */
    struct PropertyEntry
    {
      const char *name;
      const char *default_value;
      const char *documentation;
    };

    const PropertyEntry property_entries[]
        = {{"Young's modulus", "210000", "Young's modulus E (MPa), positive."},
           {"Poisson's ratio", "0.3", "Poisson's ratio nu (-1 < nu < 0.5)."},
           {"Yield stress", "240", "Initial uniaxial yield stress sigma_0 (MPa), positive."},
           {"Hardening modulus",
            "0",
            "Slope H' of the linear hardening law (MPa), not negative; 0 = perfectly plastic."},
           {"Reference plastic strain",
            "0.01",
            "eps_0 of the power law (must be > 0 when the power law is used)."},
           {"Hardening exponent", "0.2", "Exponent n of the power law, not negative."},
           {"Kinematic hardening modulus",
            "0",
            "Linear (Prager) kinematic hardening modulus H_k (MPa), not negative; 0 = none."}};
  } // namespace

  void MaterialParameters::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    for (const PropertyEntry &e : property_entries)
      prm.declare_entry(
          e.name, e.default_value, dealii::Patterns::Anything(), e.documentation + table_note);
    prm.declare_entry("Yield criterion",
                      "von Mises",
                      Selection("none|von Mises"),
                      "Yield criterion: 'none' for a purely elastic material, 'von Mises' for J2 "
                      "plasticity with isotropic (and optional linear kinematic) hardening.");
    prm.declare_entry("Hardening law",
                      "linear",
                      Selection("linear|power law"),
                      "Isotropic hardening: 'linear' sigma_y = sigma_0 + H' eps_p; 'power law' "
                      "sigma_y = sigma_0 (1 + eps_p/eps_0)^n.");
    prm.leave_subsection();
  }

  void MaterialParameters::parse_parameters(dealii::ParameterHandler &prm,
                                            const std::string        &input_directory)
  {
    prm.enter_subsection("Material");
    const auto table = [&](const std::string &name, const bool positive, const bool non_negative)
    {
      return PropertyTable::parse(
          prm.get(name), "Material/" + name, input_directory, positive, non_negative);
    };
    youngs_modulus = table("Young's modulus", true, false);
    poissons_ratio = table("Poisson's ratio", false, false);
    yield_criterion
        = prm.get("Yield criterion") == "none" ? YieldCriterion::none : YieldCriterion::von_mises;
    hardening_law = prm.get("Hardening law") == "linear" ? HardeningLawType::linear
                                                         : HardeningLawType::power_law;
    yield_stress = table("Yield stress", false, false);
    hardening_modulus = table("Hardening modulus", false, true);
    reference_plastic_strain = table("Reference plastic strain", false, true);
    hardening_exponent = table("Hardening exponent", false, true);
    kinematic_hardening_modulus = table("Kinematic hardening modulus", false, true);
    prm.leave_subsection();

    require(poissons_ratio.min_value() > -1. && poissons_ratio.max_value() < 0.5,
            "Material/Poisson's ratio",
            "must lie in (-1, 0.5)");
    if (yield_criterion != YieldCriterion::none)
    {
      require(yield_stress.min_value() > 0., "Material/Yield stress", "must be positive");
      if (hardening_law == HardeningLawType::power_law)
        require(reference_plastic_strain.min_value() > 0.,
                "Material/Reference plastic strain",
                "must be positive for the power law");
    }
  }

  std::string MaterialParameters::first_temperature_dependent_entry() const
  {
    const std::pair<const PropertyTable *, const char *> tables[]
        = {{&youngs_modulus, "Young's modulus"},
           {&poissons_ratio, "Poisson's ratio"},
           {&yield_stress, "Yield stress"},
           {&hardening_modulus, "Hardening modulus"},
           {&reference_plastic_strain, "Reference plastic strain"},
           {&hardening_exponent, "Hardening exponent"},
           {&kinematic_hardening_modulus, "Kinematic hardening modulus"}};
    for (const auto &[table, name] : tables)
      if (!table->is_constant())
        return std::string("Material/") + name;
    return "";
  }
} // namespace ausroll::material
