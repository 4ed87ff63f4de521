/**
 * @file active_set.h
 * Contact strategy `active set` (no subsection): semi-smooth Newton.
 */
#pragma once

#include <ausroll/contact/contact_strategy.h>

#include <memory>

namespace ausroll::contact
{
  /**
   * Active set (`Strategy = active set`): inside Newton, penetrating open nodes close at every
   * iterate and the reactions of each assembly judge the closed nodes at once (tension opens,
   * |R_t| > T(R_n) slips, reversed slip sticks); the assembly is repeated with the new
   * constraints (at most max_reassemblies times per iterate).
   */
  class ActiveSet : public StatusStrategy
  {
  public:
    using StatusStrategy::StatusStrategy;

    /** Re-assemblies per Newton iterate after status changes. */
    static constexpr unsigned int max_reassemblies = 4;

    void         begin_iterate(const double t) override;
    void         update_geometry(const ContactStatusSet::Vector &u) override;
    unsigned int update_at_iterate() override;

  private:
    unsigned int passes = 0; ///< assemblies at this iterate
  };

  /** Parameters of `active set`: none. */
  struct ActiveSetParameters : public StrategyParameters
  {
    static void                     declare_parameters(dealii::ParameterHandler &) {}
    std::unique_ptr<StatusStrategy> create(ContactStatusSet &nodes) const override;
  };
} // namespace ausroll::contact
