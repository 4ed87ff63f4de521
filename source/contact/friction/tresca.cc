#include <ausroll/contact/friction/tresca.h>

namespace ausroll::contact
{
  using namespace dealii;

  void declare_friction_factor(ParameterHandler &prm)
  {
    prm.declare_entry("Friction factor",
                      "0",
                      Patterns::Double(0., 1.),
                      "Friction factor m of the shear law, whose shear stress is at most m k: 0 "
                      "frictionless, 1 the full shear yield stress k = sigma_0 / sqrt(3) of the "
                      "workpiece's initial yield stress Material/Yield stress.");
  }
} // namespace ausroll::contact

AUSROLL_REGISTER_FRICTION_LAW(ausroll::contact::TrescaParameters,
                              "Tresca",
                              "Tresca",
                              "constant shear, |t_t| <= m k (Tresca/Friction factor m)")
