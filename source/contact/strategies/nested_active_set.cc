#include <ausroll/contact/strategies/nested_active_set.h>

namespace ausroll::contact
{
  NestedActiveSet::NestedActiveSet(ContactStatusSet &nodes)
      : StatusStrategy(nodes)
  {
    nodes.hold_changed_nodes(true);
  }

  void NestedActiveSet::update_geometry(const ContactStatusSet::Vector &u)
  {
    // Penetrating open nodes close at every iterate, but only those that have not changed in
    // this step; all other changes are judged at converged states (update_at_convergence()): a
    // node opened by tension that re-penetrates slightly in the next iterates would otherwise
    // chatter.
    nodes.update_geometry(u, true, true);
  }

  unsigned int NestedActiveSet::update_at_convergence(const ContactStatusSet::Vector &u,
                                                      dealii::ConditionalOStream     &log)
  {
    // The reactions of the converged state (of the last assembly) decide; penetrating open nodes
    // close.
    nodes.set_time(time);
    nodes.start_iterate();
    const unsigned int closed = nodes.close_penetrating_nodes(u);
    const unsigned int changed = nodes.update_statuses();
    if (closed + changed > 0)
      log << "      contact: " << closed << " closed, " << changed << " other status change"
          << (changed == 1 ? "" : "s") << " at the converged state" << std::endl;
    return closed + changed;
  }

  bool NestedActiveSet::backtrack_with_small_constraint_gaps() const
  {
    // curved dies leave second-order gaps after each iterate
    return true;
  }

  unsigned int NestedActiveSet::release_after_failure()
  {
    // A node that closed in stick at the end of the last step is dragged by its stick point over
    // the whole Newton pass (its status is judged only at the converged state): near a gear tip
    // that drag inverts elements. Solved again with these nodes slipping, the converged state
    // judges them as any other (a reversed slip sticks again).
    return nodes.release_fresh_sticks();
  }

  std::unique_ptr<StatusStrategy> NestedActiveSetParameters::create(ContactStatusSet &nodes) const
  {
    return std::make_unique<NestedActiveSet>(nodes);
  }
} // namespace ausroll::contact

AUSROLL_REGISTER_CONTACT_STRATEGY(
    ausroll::contact::NestedActiveSetParameters,
    "nested active set",
    "",
    "penetrating nodes close at once, the other changes (opening, stick/slip) are decided at "
    "converged states and Newton continues until none changes (robust when many nodes change "
    "status per step, as in rolling with friction)")
