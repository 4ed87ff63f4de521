/**
 * @file frictionless.h
 * Friction law `frictionless` (no subsection): no tangential force.
 */
#pragma once

#include <ausroll/contact/friction_law.h>

#include <memory>
#include <string>

namespace ausroll::contact
{
  /** `Friction = frictionless`: no tangential force, closed nodes slip. */
  class Frictionless : public FrictionLaw
  {
  public:
    std::string name() const override { return "frictionless"; }
    bool        sticks_when_closing() const override { return false; }
    bool        switches_stick_slip() const override { return false; }
    SlipLimit   slip_limit(const double, const double) const override { return SlipLimit(); }
  };

  /** Parameters of `frictionless`: none. */
  struct FrictionlessParameters : public FrictionParameters
  {
    static void                  declare_parameters(dealii::ParameterHandler &) {}
    bool                         frictionless() const override { return true; }
    std::unique_ptr<FrictionLaw> create(const FrictionContext &,
                                        const std::string &) const override;
  };
} // namespace ausroll::contact
