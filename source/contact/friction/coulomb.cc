#include <ausroll/contact/friction/coulomb.h>

namespace ausroll::contact
{
  using namespace dealii;

  void CoulombParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Friction coefficient",
                      "0",
                      Patterns::Double(0.),
                      "Coulomb coefficient mu: |t_t| <= mu p (0: frictionless).");
  }

  void CoulombParameters::parse(ParameterHandler &prm, const std::string &, const std::string &)
  {
    mu = prm.get_double("Friction coefficient");
  }

  std::unique_ptr<FrictionLaw> CoulombParameters::create(const FrictionContext &,
                                                         const std::string &) const
  {
    return std::make_unique<CoulombFriction>(mu);
  }
} // namespace ausroll::contact

AUSROLL_REGISTER_FRICTION_LAW(ausroll::contact::CoulombParameters,
                              "Coulomb",
                              "Coulomb",
                              "|t_t| <= mu p (Coulomb/Friction coefficient)")
