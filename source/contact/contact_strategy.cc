#include <ausroll/contact/contact_strategy.h>

namespace ausroll::contact
{
  // ------------------------------------------------------------------ fixed statuses (base)

  StatusStrategy::StatusStrategy(ContactStatusSet &nodes)
      : nodes(nodes)
  {
  }

  void StatusStrategy::begin_step(const ContactStatusSet::Vector &u, const double t_start)
  {
    (void)u;
    (void)t_start;
  }

  void StatusStrategy::begin_iterate(const double t)
  {
    time = t;
    nodes.set_time(t);
    nodes.start_iterate();
  }

  void StatusStrategy::update_geometry(const ContactStatusSet::Vector &u)
  {
    nodes.update_geometry(u, false);
  }

  unsigned int StatusStrategy::update_at_iterate()
  {
    return 0;
  }

  unsigned int StatusStrategy::update_at_convergence(const ContactStatusSet::Vector &u,
                                                     dealii::ConditionalOStream     &log)
  {
    (void)u;
    (void)log;
    return 0;
  }

  bool StatusStrategy::backtrack_with_small_constraint_gaps() const
  {
    return false;
  }

  StepDecision StatusStrategy::end_of_step(const double                dt,
                                           const double                end_time,
                                           dealii::ConditionalOStream &log)
  {
    (void)dt;
    (void)end_time;
    (void)log;
    return StepDecision();
  }

  void StatusStrategy::restart_step()
  {
    nodes.reset();
  }

  unsigned int StatusStrategy::release_after_failure()
  {
    return 0;
  }

  // ------------------------------------------------------------------ active set

  void ActiveSet::begin_iterate(const double t)
  {
    StatusStrategy::begin_iterate(t);
    passes = 0;
  }

  void ActiveSet::update_geometry(const ContactStatusSet::Vector &u)
  {
    // Penetrating open nodes close at every iterate (a body held by contact alone needs them at
    // once).
    nodes.update_geometry(u, true);
  }

  unsigned int ActiveSet::update_at_iterate()
  {
    // Statuses that change at this iterate (judged by the reactions of this very assembly)
    // require the constraints to be rebuilt and the system re-assembled.
    if (passes++ >= max_reassemblies)
      return 0;
    return nodes.update_statuses();
  }

  // ------------------------------------------------------------------ nested active set

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

  // ------------------------------------------------------------------ load-increment ratio

  LoadIncrementRatio::LoadIncrementRatio(ContactStatusSet &nodes, const double tolerance)
      : StatusStrategy(nodes)
      , tolerance(tolerance)
  {
  }

  void LoadIncrementRatio::begin_step(const ContactStatusSet::Vector &u, const double t_start)
  {
    substeps = 0;
    // Nodes that touch a die at the start of the step close before it (load factor zero).
    time = t_start;
    nodes.set_time(t_start);
    nodes.update_geometry(u, false);
    if (nodes.close_touching_nodes() > 0)
      nodes.promote_statuses();
  }

  StepDecision LoadIncrementRatio::end_of_step(const double                dt,
                                               const double                end_time,
                                               dealii::ConditionalOStream &log)
  {
    // End the step where the first contact status changes.
    const double alpha = nodes.event_ratio();
    if (alpha >= 1. - tolerance || ++substeps > max_substeps)
    {
      const unsigned int switched = nodes.apply_events(1. + tolerance);
      if (switched > 0)
        log << "      contact: " << switched << " status change(s) at the end of the step"
            << std::endl;
      return StepDecision();
    }
    if (alpha * dt <= 1e-9 * end_time)
    {
      // The change happens at the start of the step: switch and solve the step again.
      const unsigned int switched = nodes.apply_events(tolerance);
      nodes.promote_statuses();
      log << "      contact: " << switched << " status change(s) at the start of the step"
          << std::endl;
      return StepDecision{switched == 0, 1.};
    }
    nodes.reset();
    log << "      contact: next status change at alpha = " << alpha
        << ", step reduced to dt = " << dt * alpha << std::endl;
    return StepDecision{false, alpha};
  }

  // ------------------------------------------------------------------ factory

  std::unique_ptr<StatusStrategy> make_status_strategy(const ContactParameters &parameters,
                                                       ContactStatusSet        &nodes,
                                                       const bool               has_dies)
  {
    if (!has_dies)
      return std::make_unique<StatusStrategy>(nodes);
    switch (parameters.strategy)
    {
      case ContactStrategy::active_set:
        return std::make_unique<ActiveSet>(nodes);
      case ContactStrategy::nested_active_set:
        return std::make_unique<NestedActiveSet>(nodes);
      case ContactStrategy::load_increment_ratio:
        return std::make_unique<LoadIncrementRatio>(nodes, parameters.ratio_tolerance);
    }
    return std::make_unique<StatusStrategy>(nodes);
  }
} // namespace ausroll::contact
