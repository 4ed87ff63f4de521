#include <ausroll/contact/die_touch.h>
#include <ausroll/core/exceptions.h>

#include <algorithm>

namespace ausroll::contact
{
  template <int dim>
  void DieTouchRecord::record(const ContactOperator<dim> &contact)
  {
    touched.resize(contact.n_dies(), false);
    for (unsigned int k = 0; k < contact.n_dies(); ++k)
    {
      const auto c = contact.die_contact(k);
      touched[k] = touched[k] || c.n_stick + c.n_slip > 0;
    }
  }

  template <int dim>
  std::vector<std::string> DieTouchRecord::untouched_warnings(const ContactOperator<dim> &contact,
                                                              const unsigned int n_steps) const
  {
    std::vector<std::string> warnings;
    std::vector<bool>        seen = touched;
    seen.resize(contact.n_dies(), false); // a run without converged steps touched nothing
    if (seen.empty())
      return warnings;
    const bool any_touched = std::find(seen.begin(), seen.end(), true) != seen.end();
    for (unsigned int k = 0; k < seen.size(); ++k)
      if (!seen[k])
      {
        const std::string message
            = "Contact/Die " + std::to_string(k) + " (" + contact.die(k).name
              + ") never touched the workpiece: no node was in contact with it at the end of "
                "any of the "
              + std::to_string(n_steps)
              + " steps, so its force is zero throughout (the output is complete); check its "
                "position and Contact/Die "
              + std::to_string(k) + "/Motion";
        if (!any_touched)
          throw RunFailure(message);
        warnings.push_back(message);
      }
    return warnings;
  }

  template void                     DieTouchRecord::record(const ContactOperator<2> &);
  template void                     DieTouchRecord::record(const ContactOperator<3> &);
  template std::vector<std::string> DieTouchRecord::untouched_warnings(const ContactOperator<2> &,
                                                                       unsigned int) const;
  template std::vector<std::string> DieTouchRecord::untouched_warnings(const ContactOperator<3> &,
                                                                       unsigned int) const;
} // namespace ausroll::contact
