#include <ausroll/contact/friction/frictionless.h>

namespace ausroll::contact
{
  using namespace dealii;

  std::unique_ptr<FrictionLaw> FrictionlessParameters::create(const FrictionContext &,
                                                              const std::string &) const
  {
    return std::make_unique<Frictionless>();
  }
} // namespace ausroll::contact

AUSROLL_REGISTER_FRICTION_LAW(ausroll::contact::FrictionlessParameters,
                              "frictionless",
                              "",
                              "no tangential force, closed nodes slip freely")
