#include <ausroll/contact/friction/sticking.h>

#include <limits>

namespace ausroll::contact
{
  using namespace dealii;

  SlipLimit StickingFriction::slip_limit(const double, const double) const
  {
    return {std::numeric_limits<double>::infinity(), 0.};
  }

  std::unique_ptr<FrictionLaw> StickingParameters::create(const FrictionContext &,
                                                          const std::string &) const
  {
    return std::make_unique<StickingFriction>();
  }
} // namespace ausroll::contact

AUSROLL_REGISTER_FRICTION_LAW(ausroll::contact::StickingParameters,
                              "sticking",
                              "",
                              "no slip (mu = infinity): closed nodes stick until they open")
