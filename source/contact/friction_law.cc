#include <ausroll/contact/friction/frictionless.h>
#include <ausroll/contact/friction_law.h>

#include <cmath>

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

  FrictionContext friction_context(const material::MaterialParameters &material)
  {
    FrictionContext context;
    if (material.yield_criterion == material::YieldCriterion::none)
      return context;
    if (material.yield_stress.is_constant())
      context.shear_yield_stress = material.yield_stress.value(0.) / std::sqrt(3.);
    else
      context.yield_stress_depends_on_temperature = true;
    return context;
  }

  double required_shear_yield_stress(const FrictionContext &context, const std::string &die_path)
  {
    require(!context.yield_stress_depends_on_temperature,
            die_path + "Friction",
            "the shear friction laws take k = sigma_0 / sqrt(3) of a constant yield stress, but "
            "Material/Yield stress is a table in temperature: use Coulomb friction or a constant "
            "yield stress");
    require(context.shear_yield_stress > 0.,
            die_path + "Friction",
            "the shear friction laws need the shear yield stress k = sigma_0 / sqrt(3) of a "
            "plastic workpiece: set Material/Yield criterion = von Mises");
    return context.shear_yield_stress;
  }

  std::unique_ptr<FrictionLaw> create_friction_law(const DieParameters   &p,
                                                   const FrictionContext &context,
                                                   const std::string     &die_path)
  {
    if (p.friction == nullptr || p.friction->frictionless())
      return std::make_unique<Frictionless>();
    return p.friction->create(context, die_path);
  }
} // namespace ausroll::contact
