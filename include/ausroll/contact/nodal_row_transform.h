/**
 * @file nodal_row_transform.h
 * Affine combinations of the equilibrium equations of one node (used for friction).
 */
#pragma once

#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <array>
#include <map>

namespace ausroll::contact
{
  /**
   * An affine map applied to the equilibrium rows of one node before constraints are condensed:
   * rows(dofs) <- matrix * rows(dofs) + offset (the matrix acts on residual and tangent rows, the
   * constant offset on the residual only). For a slipping node with the slip limit
   * T(R_n) = T0 + T' R_n of its FrictionLaw, matrix = I + T' s t (x) n and offset = T0 s t turn
   * the tangential equation into t.r + s T(n.r) = 0 (friction opposing the slip direction s),
   * consistently in residual and tangent: Coulomb is matrix = I + mu s t (x) n, offset 0;
   * Tresca matrix = I, offset = m k A s t.
   */
  template <int dim>
  struct NodalRowTransform
  {
    std::array<dealii::types::global_dof_index, dim> dofs;   ///< the node's DoFs, by component
    dealii::Tensor<2, dim>                           matrix; ///< new rows = matrix * old rows ...
    dealii::Tensor<1, dim>                           offset; ///< ... + offset (added once)
  };

  /** Row transforms keyed by the node's first (x-component) DoF. */
  template <int dim>
  using RowTransforms = std::map<dealii::types::global_dof_index, NodalRowTransform<dim>>;
} // namespace ausroll::contact
