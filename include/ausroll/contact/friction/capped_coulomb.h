/**
 * @file capped_coulomb.h
 * Friction law `Coulomb capped by shear` (subsection `Contact/Die N/Coulomb capped by shear`):
 * tau = min(mu p, m k).
 */
#pragma once

#include <ausroll/contact/friction_law.h>

#include <memory>
#include <string>

namespace ausroll::contact
{
  /**
   * `Friction = Coulomb capped by shear`: tau = min(mu p, m k), i.e. T = min(mu R_n, m k A):
   * Coulomb at low pressure, constant shear where mu p would exceed the shear the workpiece can
   * carry.
   */
  class CappedCoulombFriction : public FrictionLaw
  {
  public:
    /** Coefficient @p mu, friction factor @p m, shear yield stress @p k. */
    CappedCoulombFriction(const double mu, const double m, const double k)
        : mu(mu)
        , shear(m * k)
    {
    }
    std::string name() const override { return "Coulomb capped by shear"; }
    SlipLimit   slip_limit(const double normal_force, const double area) const override
    {
      const double cap = shear * area;
      return mu * normal_force <= cap ? SlipLimit{0., mu} : SlipLimit{cap, 0.};
    }

  private:
    const double mu;
    const double shear; ///< m k
  };

  /** Subsection `Coulomb capped by shear`. */
  struct CappedCoulombParameters : public FrictionParameters
  {
    double mu = 0.; ///< `Friction coefficient` (0: frictionless)
    double m = 0.;  ///< `Friction factor` (0: frictionless)

    /** Declare its entries (the caller has entered the subsection). */
    static void                  declare_parameters(dealii::ParameterHandler &prm);
    void                         parse(dealii::ParameterHandler &prm,
                                       const std::string        &path,
                                       const std::string        &input_directory) override;
    bool                         frictionless() const override { return mu == 0. || m == 0.; }
    std::unique_ptr<FrictionLaw> create(const FrictionContext &context,
                                        const std::string     &die_path) const override;
  };
} // namespace ausroll::contact
