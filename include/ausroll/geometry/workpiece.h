/**
 * @file workpiece.h
 * Build the workpiece triangulation (coarse mesh, manifolds, boundary ids) from `Geometry`.
 */
#pragma once

#include <ausroll/geometry/geometry_parameters.h>

#include <deal.II/grid/tria.h>

namespace ausroll::geometry
{
  /**
   * Create the workpiece described by @p parameters in @p triangulation (which must be empty):
   * coarse mesh, boundary ids, manifolds on curved boundaries (so that refined boundary points lie
   * on the exact surface), then (with @p refine) `Global refinements` uniform and the local
   * refinements. Without
   * @p refine only the coarse mesh is built (as needed to load a checkpoint).
   */
  template <int dim>
  void create_workpiece(const GeometryParameters   &parameters,
                        dealii::Triangulation<dim> &triangulation,
                        const bool                  refine = true);
} // namespace ausroll::geometry
