#include <ausroll/core/exceptions.h>
#include <ausroll/material/transformation_plasticity.h>

#include <cmath>

namespace ausroll::material
{
  void TransformationPlasticityParameters::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.declare_entry(
        "TRIP coefficient",
        "0",
        dealii::Patterns::Double(),
        "Transformation-induced plasticity: K (1/MPa) of Leblond's law d eps_tp = 3/2 K s "
        "phi'(z) dz (Leblond, Devaux and Devaux, Int. J. Plasticity 5, 1989; linear regime), s "
        "the deviatoric stress, z the fraction of martensite and bainite, phi(z) = z (1 - ln "
        "z): a uniaxial stress sigma held through the whole transformation gives the strain K "
        "sigma. Not negative; 0 = no TRIP. Leblond's micromechanical value is K = 2 Delta eps / "
        "sigma_y,A (Delta eps the linear strain difference of the phases, sigma_y,A the "
        "austenite's yield stress): about 1 % and 200 to 400 MPa for martensite give 5e-5 to "
        "1e-4 1/MPa.");
    prm.declare_entry(
        "Martensite yield stress",
        "",
        dealii::Patterns::Anything(),
        "Yield stress of martensite (MPa), a number or a table in temperature as Material/Yield "
        "stress, or an expression of the carbon content C (wt%) and the temperature T, e.g. "
        "'413 + 1720*sqrt(C)' (as-quenched martensite after Krauss, Mater. Sci. Eng. A 273-275, "
        "1999; doc/theory.md section 8), evaluated at every material point's carbon content. "
        "Given, the yield stress is the linear mixture (1 - f_M - f_B) sigma_y,A + f_M "
        "(sigma_y,M + H_M alpha) + f_B sigma_y,B with sigma_y,A the hardening law of Material "
        "(the austenite). Empty: martensite yields as austenite (no mixture).");
    prm.declare_entry(
        "Martensite hardening modulus",
        "",
        dealii::Patterns::Anything(),
        "Linear isotropic hardening modulus H_M of martensite (MPa) in the point's accumulated "
        "equivalent plastic strain alpha: a number, a table in temperature or an expression of C "
        "and T, not negative. Needs Martensite yield stress. Empty: perfectly plastic "
        "martensite.");
    prm.declare_entry("Bainite yield stress",
                      "",
                      dealii::Patterns::Anything(),
                      "Yield stress of bainite (MPa, perfectly plastic), a number, a table in "
                      "temperature or an expression of C and T, in the mixture of Martensite "
                      "yield stress. Empty: bainite yields as austenite.");
  }

  void TransformationPlasticityParameters::parse_parameters(dealii::ParameterHandler &prm,
                                                            const std::string        &directory)
  {
    trip_coefficient = prm.get_double("TRIP coefficient");
    require(trip_coefficient >= 0., "Phases/TRIP coefficient", "must not be negative");
    const auto property = [&](const std::string &name, const bool positive)
    { return PhaseProperty::parse(prm.get(name), "Phases/" + name, directory, positive); };
    martensite_yield_stress = property("Martensite yield stress", true);
    martensite_yield_given = martensite_yield_stress.given();
    martensite_hardening_modulus = property("Martensite hardening modulus", false);
    bainite_yield_stress = property("Bainite yield stress", true);
    bainite_yield_given = bainite_yield_stress.given();
    require(martensite_yield_given || !martensite_hardening_modulus.given(),
            "Phases/Martensite hardening modulus",
            "hardens the martensite of the mixture: set Phases/Martensite yield stress too");
  }

  TransformationPlasticity::TransformationPlasticity(
      const TransformationPlasticityParameters &parameters_in)
      : parameters(parameters_in)
  {
  }

  double TransformationPlasticity::leblond_phi(const double z)
  {
    return z > 0. ? z * (1. - std::log(z)) : 0.;
  }

  double TransformationPlasticity::trip_compliance(const PhaseStep &phases) const
  {
    if (!(parameters.trip_coefficient > 0.))
      return 0.;
    const double z_old = phases.martensite_old + phases.bainite_old;
    const double z = phases.martensite + phases.bainite;
    if (!(z > z_old))
      return 0.;
    return 1.5 * parameters.trip_coefficient * (leblond_phi(z) - leblond_phi(z_old));
  }

  double TransformationPlasticity::austenite_weight(const PhaseStep &phases) const
  {
    double weight = 1.;
    if (parameters.martensite_yield_given)
      weight -= phases.martensite;
    if (parameters.bainite_yield_given)
      weight -= phases.bainite;
    return weight;
  }

  double TransformationPlasticity::product_yield_stress(const PhaseStep &phases,
                                                        const double     temperature) const
  {
    double sigma = 0.;
    if (parameters.martensite_yield_given)
      sigma += phases.martensite
               * parameters.martensite_yield_stress.value(phases.carbon, temperature);
    if (parameters.bainite_yield_given)
      sigma += phases.bainite * parameters.bainite_yield_stress.value(phases.carbon, temperature);
    return sigma;
  }

  double TransformationPlasticity::product_hardening(const PhaseStep &phases,
                                                     const double     temperature) const
  {
    if (!parameters.martensite_hardening_modulus.given())
      return 0.;
    return phases.martensite
           * parameters.martensite_hardening_modulus.value(phases.carbon, temperature);
  }
} // namespace ausroll::material
