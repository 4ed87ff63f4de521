/**
 * @file nodal_row_transform.h
 * Linear combinations of the equilibrium equations of one node (used for Coulomb friction).
 */
#pragma once

#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <array>
#include <map>

namespace ausroll::contact
{
  /**
   * A linear map applied to the equilibrium rows of one node before constraints are condensed:
   * rows(dofs) <- matrix * rows(dofs). For a slipping node, matrix = I + mu s t (x) n turns the
   * tangential equation into t.r + mu s n.r = 0 (Coulomb friction opposing the slip direction s),
   * consistently in residual and tangent.
   */
  template <int dim>
  struct NodalRowTransform
  {
    std::array<dealii::types::global_dof_index, dim> dofs;   ///< the node's DoFs, by component
    dealii::Tensor<2, dim>                           matrix; ///< new rows = matrix * old rows
  };

  /** Row transforms keyed by the node's first (x-component) DoF. */
  template <int dim>
  using RowTransforms = std::map<dealii::types::global_dof_index, NodalRowTransform<dim>>;
} // namespace ausroll::contact
