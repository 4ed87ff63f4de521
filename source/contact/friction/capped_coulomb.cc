#include <ausroll/contact/friction/capped_coulomb.h>

#include <ausroll/contact/friction/tresca.h>

namespace ausroll::contact
{
  using namespace dealii;

  void CappedCoulombParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Friction coefficient",
                      "0",
                      Patterns::Double(0.),
                      "Coulomb coefficient mu of the low-pressure part (0: frictionless).");
    declare_friction_factor(prm);
  }

  void
  CappedCoulombParameters::parse(ParameterHandler &prm, const std::string &, const std::string &)
  {
    mu = prm.get_double("Friction coefficient");
    m = prm.get_double("Friction factor");
  }

  std::unique_ptr<FrictionLaw> CappedCoulombParameters::create(const FrictionContext &context,
                                                               const std::string &die_path) const
  {
    return std::make_unique<CappedCoulombFriction>(
        mu, m, required_shear_yield_stress(context, die_path));
  }
} // namespace ausroll::contact

AUSROLL_REGISTER_FRICTION_LAW(ausroll::contact::CappedCoulombParameters,
                              "Coulomb capped by shear",
                              "Coulomb capped by shear",
                              "|t_t| <= min(mu p, m k)")
