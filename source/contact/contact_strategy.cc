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

  // ------------------------------------------------------------------ factory

  std::unique_ptr<StatusStrategy> make_status_strategy(const ContactParameters &parameters,
                                                       ContactStatusSet        &nodes,
                                                       const bool               has_dies)
  {
    if (!has_dies)
      return std::make_unique<StatusStrategy>(nodes);
    if (parameters.strategy_parameters)
      return parameters.strategy_parameters->create(nodes);
    return StrategyRegistry::instance()
        .get(parameters.strategy, "Contact/Strategy")
        .make()
        ->create(nodes);
  }
} // namespace ausroll::contact
