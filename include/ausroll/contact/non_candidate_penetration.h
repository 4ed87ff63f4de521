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
#include <set>
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
    /** The deepest node of a boundary that is not a candidate of a die and lies inside it. */
    struct Penetration
    {
      bool               found = false; ///< a node lies deeper than the tolerance
      unsigned int       die = 0;       ///< the die it passes through
      unsigned int       boundary = 0;  ///< its boundary id (the first, at a corner)
      double             depth = 0.;    ///< how deep (mm)
      dealii::Point<dim> X;             ///< its reference position
    };

    /** Boundary nodes of @p dof_handler (support points and DoFs), by boundary id (call after
        every change of the DoFs). */
    void setup(const dealii::Mapping<dim> &mapping, const dealii::DoFHandler<dim> &dof_handler);

    /**
     * The deepest node, over all ranks, of a boundary that is not a candidate of die k and lies
     * more than @p tolerance inside die k at displacement @p u (ghosted) and time @p time (found =
     * false if there is none). Collective.
     */
    Penetration find(const ContactOperator<dim>                  &contact,
                     const dealii::TrilinosWrappers::MPI::Vector &u,
                     const double                                 time,
                     const double                                 tolerance,
                     const MPI_Comm                               comm) const;

    /**
     * As find(), but only nodes that were outside the die (gap above -@p tolerance) at the
     * start of the step (displacement @p u_start at @p t_start): nodes that cross the die
     * surface in this step. A node that is already "inside" a die far from where it touches the
     * workpiece (an unbounded flat die, the back of a shoulder) is not one.
     */
    Penetration find_crossing(const ContactOperator<dim>                  &contact,
                              const dealii::TrilinosWrappers::MPI::Vector &u,
                              const double                                 time,
                              const dealii::TrilinosWrappers::MPI::Vector &u_start,
                              const double                                 t_start,
                              const double                                 tolerance,
                              const MPI_Comm                               comm) const;

    /**
     * The first time find() finds a node: the warning that the boundary passes through the die
     * (results no longer those of the forming process, the entry to change); else an empty
     * string. Collective.
     */
    std::string check(const ContactOperator<dim>                  &contact,
                      const dealii::TrilinosWrappers::MPI::Vector &u,
                      const double                                 time,
                      const unsigned int                           step,
                      const double                                 tolerance,
                      const MPI_Comm                               comm);

    /**
     * `Contact/Penetrating boundaries = add`: the crossing found by find_crossing() if its
     * boundary is to become a candidate of the die, found = false if there is none or if the
     * boundary is among @p held (prescribed displacements, a symmetry axis or a clamp: as a
     * contact candidate its constraints would conflict; check() warns about it). Collective.
     */
    Penetration boundary_to_add(const ContactOperator<dim>                  &contact,
                                const dealii::TrilinosWrappers::MPI::Vector &u,
                                const double                                 time,
                                const dealii::TrilinosWrappers::MPI::Vector &u_start,
                                const double                                 t_start,
                                const double                                 tolerance,
                                const std::set<unsigned int>                &held,
                                const MPI_Comm                               comm) const;

    /** The note of the run log when boundary_to_add() found @p p in step @p step at @p time. */
    static std::string added_note(const Penetration &p,
                                  const std::string &die_name,
                                  const unsigned int step,
                                  const double       time);

    /** The words naming @p p (boundary, die, depth, node, step, time) that begin both the
        warning of check() and the note of `Contact/Penetrating boundaries = add`. */
    static std::string describe(const Penetration &p,
                                const std::string &die_name,
                                const unsigned int step,
                                const double       time);

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
