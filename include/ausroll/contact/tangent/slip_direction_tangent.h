/**
 * @file slip_direction_tangent.h
 * The derivative of the slip direction of slipping contact nodes in the tangent.
 */
#pragma once

#include <ausroll/contact/tangent/contact_tangent_term.h>

namespace ausroll::contact
{
  /**
   * The consistent linearisation of the isotropic friction cone in 3D. A slipping node whose
   * slip s since its slip started is longer than the operator's slip length has d = s / |s| at
   * every iterate (ContactOperator::update_geometry(), ContactOperator::followed_slips()), and
   * its friction force -T(R_n) d, R_n the normal force of this assembly, changes with the node's
   * position x by -T (P - d (x) d) / |s| dx (P = I - n (x) n: the projection of the node on the
   * die moves with the tangential part of dx). The rows of the node's equations (r + T d = 0)
   * get + T / |s| (P - d (x) d) in the columns of its own DoFs, condensed with the Newton
   * constraints (inhomogeneities into the right-hand side, as the assembly does). Curvature
   * terms of the tangents (|s| / R against 1) are left out.
   *
   * 2D: no term. The slip direction is the sign of the slip along the die tangent, held over
   * the step: it does not depend on the iterate.
   */
  template <int dim>
  class SlipDirectionTangent : public ContactTangentTerm<dim>
  {
  public:
    std::string  name() const override { return "slip direction"; }
    unsigned int add_to(const ContactTangentInput<dim>         &input,
                        dealii::TrilinosWrappers::SparseMatrix &matrix,
                        dealii::TrilinosWrappers::MPI::Vector  &rhs) const override;
  };
} // namespace ausroll::contact
