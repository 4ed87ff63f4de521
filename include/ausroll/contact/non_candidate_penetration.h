/**
 * @file non_candidate_penetration.h
 * A workpiece boundary that is not a contact candidate of a die but passes through it.
 */
#pragma once

#include <ausroll/contact/contact_operator.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/trilinos_vector.h>

#include <array>
#include <string>
#include <vector>

namespace ausroll::contact
{
  /**
   * Only the boundaries listed in a die's `Candidate boundaries` can touch it; any other boundary
   * passes through the rigid die unhindered. That is what happens in an upsetting with the platen
   * on the top face only when the free side surface folds over the corner onto the platen
   * (doc/scenes/hard_cases.md, section 6): the result is no longer the forming process, and the
   * elements at the corner fold until Newton fails. After every converged step check() looks
   * at the boundary nodes of the other boundaries and returns, the first time one lies deeper
   * in a die than the tolerance, a message naming the boundary, the die, the place, the step and
   * the remedy (add the boundary to the die's candidates); later calls return an empty string.
   */
  template <int dim>
  class NonCandidatePenetration
  {
  public:
    /** Boundary nodes of @p dof_handler (support points and DoFs), by boundary id (call after
        every change of the DoFs). */
    void setup(const dealii::Mapping<dim> &mapping, const dealii::DoFHandler<dim> &dof_handler);

    /**
     * The first time a node of a boundary that is not a candidate of die k lies more than
     * @p tolerance inside die k at displacement @p u (ghosted) and time @p time: the message;
     * else an empty string. Collective.
     */
    std::string check(const ContactOperator<dim>                  &contact,
                      const dealii::TrilinosWrappers::MPI::Vector &u,
                      const double                                 time,
                      const unsigned int                           step,
                      const double                                 tolerance,
                      const MPI_Comm                               comm);

  private:
    struct BoundaryNode
    {
      std::vector<unsigned int> boundary_ids; ///< all boundaries the node lies on
      dealii::Point<dim>        X;
      std::array<dealii::types::global_dof_index, dim> dofs;
    };
    std::vector<BoundaryNode> nodes; ///< locally owned boundary nodes
    bool                      reported = false;
  };
} // namespace ausroll::contact
