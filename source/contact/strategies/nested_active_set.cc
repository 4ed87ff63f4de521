#include <ausroll/contact/strategies/nested_active_set.h>

namespace ausroll::contact
{
  NestedActiveSet::NestedActiveSet(ContactStatusSet  &nodes,
                                   const bool         fresh_sticks_slip,
                                   const unsigned int changes_inside_newton)
      : StatusStrategy(nodes)
      , fresh_sticks_slip(fresh_sticks_slip)
      , changes_inside_newton(changes_inside_newton)
  {
    nodes.hold_changed_nodes(true);
  }

  void NestedActiveSet::begin_step(const ContactStatusSet::Vector &u, const double t_start)
  {
    StatusStrategy::begin_step(u, t_start);
    // A node that closed in stick at the end of the last step is dragged by its stick point over
    // the first Newton pass of this one and, where the contact slides (the gear's flank), slips
    // at the first converged state with a tangential force far beyond the slip limit: the pass
    // that follows starts from a large residual and creeps (doc/studies/newton_economy.md,
    // section 6). Slipping from the start, such a node sticks again at the first converged state
    // if its slip reverses.
    if (fresh_sticks_slip)
      nodes.release_fresh_sticks();
  }

  void NestedActiveSet::restart_step()
  {
    StatusStrategy::restart_step();
    if (fresh_sticks_slip)
      nodes.release_fresh_sticks();
  }

  void NestedActiveSet::begin_iterate(const double t)
  {
    StatusStrategy::begin_iterate(t);
    passes = 0;
  }

  void NestedActiveSet::update_geometry(const ContactStatusSet::Vector &u)
  {
    // Penetrating open nodes close at every iterate, but only those that have not changed in
    // this step; all other changes are judged at converged states (update_at_convergence()): a
    // node opened by tension that re-penetrates slightly in the next iterates would otherwise
    // chatter.
    nodes.update_geometry(u, true, true);
  }

  unsigned int NestedActiveSet::update_at_iterate()
  {
    // Judged at every iterate as by the active set, but a node only for its first
    // changes_inside_newton changes of the step: after that it is held (no chatter between
    // iterates) and judged at converged states only.
    if (changes_inside_newton == 0 || passes++ >= max_reassemblies)
      return 0;
    return nodes.update_statuses(changes_inside_newton);
  }

  unsigned int NestedActiveSet::update_at_convergence(const ContactStatusSet::Vector &u,
                                                      dealii::ConditionalOStream     &log)
  {
    // The reactions of the converged state (of the last assembly) decide; penetrating open nodes
    // close.
    nodes.set_time(time);
    nodes.start_iterate();
    const unsigned int closed = nodes.close_penetrating_nodes(u);
    const unsigned int changed = nodes.update_statuses(ContactStatusSet::no_change_limit);
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
    return fresh_sticks_slip ? 0 : nodes.release_fresh_sticks();
  }

  void NestedActiveSetParameters::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.declare_entry(
        "Fresh sticks slip",
        "false",
        dealii::Patterns::Bool(),
        "Every load step starts with the nodes that closed in stick in the last step slipping "
        "(friction force of the sign of their last tangential reaction); a reversed slip sticks "
        "again at the first converged state. false: they start sticking and slip only after a "
        "converged pass (or when a failed attempt is solved again). See "
        "doc/studies/newton_economy.md, section 6.");
    prm.declare_entry(
        "Status changes inside Newton",
        "0",
        dealii::Patterns::Integer(0),
        "N > 0: the contact statuses are also judged at every Newton iterate (by the reactions of "
        "that assembly, as with Strategy = active set), a node only while it has changed status "
        "fewer than N times in the load step; after that it is held and judged only at converged "
        "states (no chatter). 0: statuses other than closing are judged only at converged states. "
        "See doc/studies/newton_economy.md, section 7.");
  }

  void NestedActiveSetParameters::parse(dealii::ParameterHandler &prm,
                                        const std::string &,
                                        const std::string &)
  {
    fresh_sticks_slip = prm.get_bool("Fresh sticks slip");
    changes_inside_newton = prm.get_integer("Status changes inside Newton");
  }

  std::unique_ptr<StatusStrategy> NestedActiveSetParameters::create(ContactStatusSet &nodes) const
  {
    return std::make_unique<NestedActiveSet>(nodes, fresh_sticks_slip, changes_inside_newton);
  }
} // namespace ausroll::contact

AUSROLL_REGISTER_CONTACT_STRATEGY(
    ausroll::contact::NestedActiveSetParameters,
    "nested active set",
    "Nested active set",
    "penetrating nodes close at once, the other changes (opening, stick/slip) are decided at "
    "converged states and Newton continues until none changes (robust when many nodes change "
    "status per step, as in rolling with friction)")
