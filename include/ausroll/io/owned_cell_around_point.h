/**
 * @file owned_cell_around_point.h
 * The locally owned cell that contains a point, for point evaluations on a distributed mesh
 * (monitor points, line probes).
 */
#pragma once

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>

#include <optional>
#include <utility>

namespace ausroll::io
{
  /**
   * A locally owned active cell of @p dof_handler that contains @p p (to @p tolerance in
   * reference coordinates) and the point's reference coordinates in it (projected onto the unit
   * cell: a point just outside a curved boundary, where the mapping's polynomial departs from the
   * exact surface, is evaluated at the nearest point of the cell), or
   * nothing if this rank owns no such cell. A point on a face, edge or vertex between cells owned
   * by different ranks is found by each of those ranks (deal.II's single-cell search may return a
   * ghost cell on each of them, so that no rank would own the point).
   */
  template <int dim>
  std::optional<
      std::pair<typename dealii::DoFHandler<dim>::active_cell_iterator, dealii::Point<dim>>>
  owned_cell_around_point(const dealii::Mapping<dim>    &mapping,
                          const dealii::DoFHandler<dim> &dof_handler,
                          const dealii::Point<dim>      &p,
                          const double                   tolerance = 1e-10);
} // namespace ausroll::io
