#include <ausroll/contact/strategies/load_increment_ratio.h>

namespace ausroll::contact
{
  using namespace dealii;

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

  void LoadIncrementRatioParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Ratio tolerance",
                      "1e-3",
                      Patterns::Double(0., 0.5),
                      "A step whose ratio alpha is above 1 - tolerance is accepted.");
  }

  void LoadIncrementRatioParameters::parse(ParameterHandler &prm,
                                           const std::string &,
                                           const std::string &)
  {
    tolerance = prm.get_double("Ratio tolerance");
  }

  std::unique_ptr<StatusStrategy>
  LoadIncrementRatioParameters::create(ContactStatusSet &nodes) const
  {
    return std::make_unique<LoadIncrementRatio>(nodes, tolerance);
  }
} // namespace ausroll::contact

AUSROLL_REGISTER_CONTACT_STRATEGY(
    ausroll::contact::LoadIncrementRatioParameters,
    "load increment ratio",
    "Load increment ratio",
    "statuses are fixed during a sub-step and each step is scaled to the next status change "
    "(NOFEAP, Okamoto; Load increment ratio/Ratio tolerance)")
