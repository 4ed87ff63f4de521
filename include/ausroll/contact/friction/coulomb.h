/**
 * @file coulomb.h
 * Friction law `Coulomb` (subsection `Contact/Die N/Coulomb`): |t_t| <= mu p.
 */
#pragma once

#include <ausroll/contact/friction_law.h>

#include <memory>
#include <string>

namespace ausroll::contact
{
  /** `Friction = Coulomb`: T = mu R_n (`Coulomb/Friction coefficient` mu). */
  class CoulombFriction : public FrictionLaw
  {
  public:
    explicit CoulombFriction(const double mu)
        : mu(mu)
    {
    }
    std::string name() const override { return "Coulomb"; }
    SlipLimit   slip_limit(const double, const double) const override { return {0., mu}; }

  private:
    const double mu;
  };

  /** Subsection `Coulomb`. */
  struct CoulombParameters : public FrictionParameters
  {
    double mu = 0.; ///< `Friction coefficient` (0: frictionless)

    /** Declare `Friction coefficient` (the caller has entered the subsection). */
    static void                  declare_parameters(dealii::ParameterHandler &prm);
    void                         parse(dealii::ParameterHandler &prm,
                                       const std::string        &path,
                                       const std::string        &input_directory) override;
    bool                         frictionless() const override { return mu == 0.; }
    std::unique_ptr<FrictionLaw> create(const FrictionContext &,
                                        const std::string &) const override;
  };
} // namespace ausroll::contact
