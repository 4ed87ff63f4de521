#include <ausroll/contact/tangent/contact_tangent_term.h>
#include <ausroll/contact/tangent/curvature_tangent.h>
#include <ausroll/contact/tangent/slip_direction_tangent.h>

namespace ausroll::contact
{
  template <int dim>
  std::vector<std::unique_ptr<ContactTangentTerm<dim>>>
  create_tangent_terms(const ContactParameters &parameters)
  {
    std::vector<std::unique_ptr<ContactTangentTerm<dim>>> terms;
    terms.push_back(std::make_unique<SlipDirectionTangent<dim>>());
    if (parameters.curvature_tangent)
      terms.push_back(std::make_unique<CurvatureTangent<dim>>());
    return terms;
  }

  template std::vector<std::unique_ptr<ContactTangentTerm<2>>>
  create_tangent_terms<2>(const ContactParameters &);
  template std::vector<std::unique_ptr<ContactTangentTerm<3>>>
  create_tangent_terms<3>(const ContactParameters &);
} // namespace ausroll::contact
