/**
 * @file contact_tangent_term.h
 * The Newton terms of the contact that the assembled tangent does not hold: the interface, what
 * they read at an assembly, and the one list of them that the parameters ask for.
 */
#pragma once

#include <ausroll/contact/contact_parameters.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>
#include <string>
#include <vector>

namespace ausroll::contact
{
  template <int dim>
  class ContactOperator;

  /** What a contact tangent term reads at an assembly (all after the reactions of this
      assembly were computed: ContactOperator::compute_reactions()). */
  template <int dim>
  struct ContactTangentInput
  {
    /** The node states (statuses, projections, forces), the dies and the friction row
        transforms of this assembly. */
    const ContactOperator<dim> &contact;
    /** The Newton constraints of this assembly, the contact lines included (the matrix and the
        right-hand side were condensed with them). */
    const dealii::AffineConstraints<double>     &constraints;
    const dealii::TrilinosWrappers::MPI::Vector &u;        ///< displacement (ghosted)
    const dealii::TrilinosWrappers::MPI::Vector &residual; ///< f_int - f_ext with the reactions
                                                           ///< (ghosted)
    double time = 0.;                                      ///< pseudo-time (die poses)
  };

  /**
   * A contact contribution to the Newton tangent beyond the assembled one (the friction row
   * transforms of the slipping nodes act inside the assembly, NodalRowTransform): the derivative
   * of the slip direction, the curvature of the die. A term is one file pair in
   * `contact/tangent/` and one line in create_tangent_terms(); where it has nothing to add (a
   * dimension, a parameter), its own code says so. The EquilibriumProblem adds every term of
   * ContactOperator::tangent_terms() to every assembled matrix.
   */
  template <int dim>
  class ContactTangentTerm
  {
  public:
    virtual ~ContactTangentTerm() = default;

    /** Short name for logs and tests. */
    virtual std::string name() const = 0;

    /** The DoFs changed (call after every change of the DoFs; ContactOperator::setup() does). */
    virtual void setup(const dealii::Mapping<dim> & /*mapping*/,
                       const dealii::DoFHandler<dim> & /*dof_handler*/)
    {
    }

    /**
     * Add the term at the state @p input to @p matrix and @p rhs (assembled, condensed and
     * compressed; compressed again here). Returns the number of nodes with a term on this rank.
     */
    virtual unsigned int add_to(const ContactTangentInput<dim>         &input,
                                dealii::TrilinosWrappers::SparseMatrix &matrix,
                                dealii::TrilinosWrappers::MPI::Vector  &rhs) const = 0;
  };

  /** The contact tangent terms of @p parameters, in the order they are added: the slip
      direction, then the curvature (`Contact/Curvature tangent`). */
  template <int dim>
  std::vector<std::unique_ptr<ContactTangentTerm<dim>>>
  create_tangent_terms(const ContactParameters &parameters);
} // namespace ausroll::contact
