/**
 * @file sticking.h
 * Friction law `sticking` (no subsection): no slip.
 */
#pragma once

#include <ausroll/contact/friction_law.h>

#include <memory>
#include <string>

namespace ausroll::contact
{
  /** `Friction = sticking`: no slip (mu = infinity), closed nodes stick until they open. */
  class StickingFriction : public FrictionLaw
  {
  public:
    std::string name() const override { return "sticking"; }
    bool        switches_stick_slip() const override { return false; }
    SlipLimit   slip_limit(const double, const double) const override;
  };

  /** Parameters of `sticking`: none. */
  struct StickingParameters : public FrictionParameters
  {
    static void                  declare_parameters(dealii::ParameterHandler &) {}
    std::unique_ptr<FrictionLaw> create(const FrictionContext &,
                                        const std::string &) const override;
  };
} // namespace ausroll::contact
