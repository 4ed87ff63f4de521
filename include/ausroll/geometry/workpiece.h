/**
 * @file workpiece.h
 * Build the workpiece triangulation (coarse mesh, manifolds, boundary ids) from `Geometry`.
 */
#pragma once

#include <ausroll/geometry/geometry_parameters.h>

#include <deal.II/grid/tria.h>

#include <functional>
#include <string>
#include <vector>

namespace ausroll::geometry
{
  /** Most coarse cells a generated workpiece may have (checked before the mesh is built). */
  constexpr double max_coarse_cells = 1e6;
  /** Most cells after `Global refinements` (estimated before refining). */
  constexpr double max_cells = 4e6;
  /** Most degrees of freedom (estimated from the cells and the degree before distributing). */
  constexpr double max_dofs = 2e7;

  /**
   * InputError naming `Model/Polynomial degree` and the refinements if @p n_cells cells of degree
   * @p degree in @p dim dimensions give more than max_dofs unknowns (about n_cells p^dim dim).
   */
  void
  require_dof_estimate(const double n_cells, const unsigned int degree, const unsigned int dim);

  /**
   * Create the workpiece described by @p parameters in @p triangulation (which must be empty):
   * coarse mesh, boundary ids, manifolds on curved boundaries (so that refined boundary points lie
   * on the exact surface), then (with @p refine) `Global refinements` uniform and the local
   * refinements. Without
   * @p refine only the coarse mesh is built (as needed to load a checkpoint). @p check_cells, if
   * given, is called with the number of cells the global refinements will make before they are
   * made (the memory estimate of the whole discretisation refuses a too large input there).
   */
  template <int dim>
  void create_workpiece(const GeometryParameters                  &parameters,
                        dealii::Triangulation<dim>                &triangulation,
                        const bool                                 refine = true,
                        const std::function<void(double n_cells)> &check_cells = {});

  /**
   * InputError naming @p entry unless every id of @p ids is a boundary id of @p triangulation
   * (the shared check of every boundary-id entry: conditions, die candidates, reactions, ...).
   */
  template <int dim>
  void require_boundary_ids(const dealii::Triangulation<dim> &triangulation,
                            const std::vector<unsigned int>  &ids,
                            const std::string                &entry);

  /**
   * InputError naming @p entry if the workpiece reaches x < 0 (an axisymmetric body's x is its
   * radius).
   */
  template <int dim>
  void require_off_axis(const dealii::Triangulation<dim> &triangulation, const std::string &entry);
} // namespace ausroll::geometry
