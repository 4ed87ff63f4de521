/**
 * @file curvature_tangent.h
 * The curvature part of the tangent of slipping contact nodes on curved dies
 * (`Contact/Curvature tangent`).
 */
#pragma once

#include <ausroll/contact/tangent/contact_tangent_term.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <unordered_map>

namespace ausroll::contact
{
  /**
   * A slipping node (frictionless or Coulomb) is held on its die by the constraint line
   * u_a = c u_b + b with c = -n_b / n_a (n the die normal at the node's projection, a the
   * component with the larger normal entry, b the other one): its one remaining equation is the
   * condensed row E = v . (T r) with v = e_b + c e_a (a vector along the die tangent), r the
   * node's residual (its reaction) and T the friction row transform (I for frictionless,
   * I + mu s t (x) n for Coulomb). The assembled tangent holds v . T (dr/du) v with v, T frozen
   * at the iterate; on a curved die the normal turns as the node slides, dn = (dn/ds) ds,
   * and E changes also by
   *
   *   dE = [ (dc/du_b) (T r)_a + (v . w) (dn/du_b . r) ] du_b,   w = (T - I) n,
   *   dc/du_b = -(dn_b n_a - n_b dn_a) / n_a^2,   dn/du_b = (dn/ds) (t . v),
   *
   * (the term of dT along dt vanishes because v is normal to n). Without it Newton converges
   * only linearly once the reactions are large, with the ratio ~ R_n / (R K_tt) (R the die
   * radius): in the punch of doc/scenes/hard_cases.md the last iterations drop by a factor of
   * 1e-3 to 1e-4 instead of squaring the residual, in the elastic punch by 0.02. add_to() adds
   * this term to the diagonal entry of u_b; dn/ds is taken from two projections a small
   * distance apart along the tangent (flat dies: zero, nothing is added). The change of the
   * normal by the inhomogeneity b of the constraint (the gap, of second order near
   * convergence) is left out.
   *
   * Works on the data that ContactOperator makes public: the constraint lines it adds, its row
   * transforms and its dies; a node is taken as slipping when its two DoFs are tied by one
   * constraint line (stick lines, Dirichlet lines and hanging-node lines look different).
   *
   * 3D (node_term_3d()): the slip line u_k = sum_j c_j u_j + b (c_j = -n_j / n_k, k the
   * component with the largest normal entry) leaves the equations E_j = v_j . (T r) of the two
   * free components j, v_j = e_j + c_j e_k, and the same derivation gives the 2 x 2 block
   *
   *   dE_j/du_j' = (dc_j/du_j') (T r)_k + (v_j . w) (dn/du_j' . r),   dn/du_j' = W v_j',
   *
   * W = dn/dx the die's curvature along its tangent plane (taken from projections a small
   * distance apart along each tangent), the change of the slip direction d inside T left to
   * SlipDirectionTangent (in 2D it vanishes).
   */
  template <int dim>
  class CurvatureTangent : public ContactTangentTerm<dim>
  {
  public:
    std::string name() const override { return "curvature"; }

    /** Component and support point of each locally relevant DoF of @p dof_handler. */
    void setup(const dealii::Mapping<dim>    &mapping,
               const dealii::DoFHandler<dim> &dof_handler) override;

    /**
     * Add the curvature term of every locally owned slipping node at the displacement and
     * residual of @p input to @p matrix (the right-hand side does not change). Returns the
     * number of nodes with a nonzero term on this rank.
     */
    unsigned int add_to(const ContactTangentInput<dim>         &input,
                        dealii::TrilinosWrappers::SparseMatrix &matrix,
                        dealii::TrilinosWrappers::MPI::Vector  &rhs) const override;

    /**
     * The term for one node, exposed for the unit test: normal @p normal and its derivative
     * @p dn_ds along the unit tangent @p tangent, the constraint coefficient @p c of line a
     * (u_a = c u_b + ...), the node's residual @p r and friction row transform @p T, components
     * @p a (constrained) and @p b (free). Returns dE/du_b minus the frozen part.
     */
    static double node_term(const dealii::Tensor<1, 2> &normal,
                            const dealii::Tensor<1, 2> &dn_ds,
                            const dealii::Tensor<1, 2> &tangent,
                            const double                c,
                            const dealii::Tensor<1, 2> &r,
                            const dealii::Tensor<2, 2> &T,
                            const unsigned int          a,
                            const unsigned int          b);

    /**
     * 3D: the term for one node, exposed for the unit test: normal @p normal, its derivatives
     * @p dn_dt along the unit tangents @p tangents, the node's residual @p r and friction row
     * transform @p T, the constrained component @p k. Returns the block dE_j/du_j' minus the
     * frozen part in rows j and columns j' (the free components; row and column k are zero).
     */
    static dealii::Tensor<2, 3> node_term_3d(const dealii::Tensor<1, 3>                &normal,
                                             const std::array<dealii::Tensor<1, 3>, 2> &dn_dt,
                                             const std::array<dealii::Tensor<1, 3>, 2> &tangents,
                                             const unsigned int                         k,
                                             const dealii::Tensor<1, 3>                &r,
                                             const dealii::Tensor<2, 3>                &T);

  private:
    /** 3D: add_to() for the slip lines with two entries. */
    unsigned int add_to_3d(const ContactTangentInput<dim>         &input,
                           dealii::TrilinosWrappers::SparseMatrix &matrix) const;

    struct DofInfo
    {
      unsigned int       component = 0;
      dealii::Point<dim> support_point;
    };
    std::unordered_map<dealii::types::global_dof_index, DofInfo> dofs;
    dealii::IndexSet                                             owned;
  };
} // namespace ausroll::contact
