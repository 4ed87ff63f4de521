#include <ausroll/contact/friction_law.h>

#include <cmath>
#include <limits>

namespace ausroll::contact
{
  FrictionResponse FrictionLaw::respond(const double normal_force,
                                        const double trial,
                                        const double area,
                                        const double tolerance) const
  {
    FrictionResponse response;
    const bool       slips
        = !sticks_when_closing()
          || (switches_stick_slip()
              && std::abs(trial) > slip_limit(normal_force, area).value(normal_force) + tolerance);
    if (!slips)
    {
      response.tangential = trial;
      return response;
    }
    const SlipLimit limit = slip_limit(normal_force, area);
    const double    sign = trial > 0. ? 1. : (trial < 0. ? -1. : 0.);
    response.slip = true;
    response.tangential = sign * limit.value(normal_force);
    response.d_d_normal = sign * limit.slope;
    response.d_d_trial = 0.;
    return response;
  }

  SlipLimit StickingFriction::slip_limit(const double, const double) const
  {
    return {std::numeric_limits<double>::infinity(), 0.};
  }

  std::unique_ptr<FrictionLaw> create_friction_law(const DieParameters &p)
  {
    switch (p.friction)
    {
      case FrictionLawType::frictionless:
        return std::make_unique<Frictionless>();
      case FrictionLawType::coulomb:
        return std::make_unique<CoulombFriction>(p.friction_coefficient);
      case FrictionLawType::sticking:
        return std::make_unique<StickingFriction>();
      case FrictionLawType::tresca:
        return std::make_unique<TrescaFriction>(p.friction_factor, p.shear_yield_stress);
      case FrictionLawType::coulomb_capped_by_shear:
        return std::make_unique<CappedCoulombFriction>(
            p.friction_coefficient, p.friction_factor, p.shear_yield_stress);
    }
    return std::make_unique<Frictionless>();
  }
} // namespace ausroll::contact
