#include <ausroll/contact/strategies/active_set.h>

namespace ausroll::contact
{
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
    return nodes.update_statuses(ContactStatusSet::no_change_limit);
  }

  std::unique_ptr<StatusStrategy> ActiveSetParameters::create(ContactStatusSet &nodes) const
  {
    return std::make_unique<ActiveSet>(nodes);
  }
} // namespace ausroll::contact

AUSROLL_REGISTER_CONTACT_STRATEGY(ausroll::contact::ActiveSetParameters,
                                  "active set",
                                  "",
                                  "contact statuses are updated inside the Newton loop "
                                  "(semi-smooth Newton)")
