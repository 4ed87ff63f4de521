/**
 * @file nested_active_set.h
 * Contact strategy `nested active set` (no subsection): statuses judged at converged states.
 */
#pragma once

#include <ausroll/contact/contact_strategy.h>

#include <memory>

namespace ausroll::contact
{
  /**
   * Nested active set (`Strategy = nested active set`): penetrating open nodes close at every
   * iterate unless they have changed in this step; all other status changes are judged at
   * converged states (an outer loop around Newton), a changed node only after a solve with its
   * new constraint. A node opened by tension that re-penetrates slightly in the next iterates does
   * not chatter. The line search may backtrack with second-order gaps on curved dies.
   */
  class NestedActiveSet : public StatusStrategy
  {
  public:
    explicit NestedActiveSet(ContactStatusSet &nodes);

    void         update_geometry(const ContactStatusSet::Vector &u) override;
    unsigned int update_at_convergence(const ContactStatusSet::Vector &u,
                                       dealii::ConditionalOStream     &log) override;
    bool         backtrack_with_small_constraint_gaps() const override;
    /** Nodes that closed in the last step and stick slip instead
        (ContactStatusSet::release_fresh_sticks()). */
    unsigned int release_after_failure() override;
  };

  /** Parameters of `nested active set`: none. */
  struct NestedActiveSetParameters : public StrategyParameters
  {
    static void                     declare_parameters(dealii::ParameterHandler &) {}
    std::unique_ptr<StatusStrategy> create(ContactStatusSet &nodes) const override;
  };
} // namespace ausroll::contact
