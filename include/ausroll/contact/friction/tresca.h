/**
 * @file tresca.h
 * Friction law `Tresca` (subsection `Contact/Die N/Tresca`): constant shear tau = m k.
 */
#pragma once

#include <ausroll/contact/friction_law.h>

#include <memory>
#include <string>

namespace ausroll::contact
{
  /**
   * `Friction = Tresca`: constant shear, tau = m k on the contact area whatever the pressure
   * (the friction-factor law of forming practice); T = m k A. k = sigma_0 / sqrt(3) is the shear
   * yield stress of the workpiece from its initial yield stress `Material/Yield stress` (von
   * Mises, handed in by FrictionContext), m the `Friction factor` (0: frictionless, 1: full
   * sticking friction of a rigid-plastic workpiece).
   */
  class TrescaFriction : public FrictionLaw
  {
  public:
    /** Friction factor @p m, shear yield stress @p k. */
    TrescaFriction(const double m, const double k)
        : shear(m * k)
    {
    }
    std::string name() const override { return "Tresca"; }
    SlipLimit   slip_limit(const double, const double area) const override
    {
      return {shear * area, 0.};
    }

  private:
    const double shear; ///< m k
  };

  /** Declare the `Friction factor` entry of a shear law (Tresca, capped Coulomb, Levanov). */
  void declare_friction_factor(dealii::ParameterHandler &prm);

  /**
   * The subsection of a shear law @p Law whose only entry is the `Friction factor` m (Tresca,
   * Levanov): frictionless for m = 0, else Law(m, k) with the workpiece's k.
   */
  template <class Law>
  struct FrictionFactorParameters : public FrictionParameters
  {
    double m = 0.; ///< `Friction factor` (0: frictionless)

    /** Declare `Friction factor` (the caller has entered the subsection). */
    static void declare_parameters(dealii::ParameterHandler &prm) { declare_friction_factor(prm); }
    void parse(dealii::ParameterHandler &prm, const std::string &, const std::string &) override
    {
      m = prm.get_double("Friction factor");
    }
    bool                         frictionless() const override { return m == 0.; }
    std::unique_ptr<FrictionLaw> create(const FrictionContext &context,
                                        const std::string     &die_path) const override
    {
      return std::make_unique<Law>(m, required_shear_yield_stress(context, die_path));
    }
  };

  /** Subsection `Tresca`. */
  using TrescaParameters = FrictionFactorParameters<TrescaFriction>;
} // namespace ausroll::contact
