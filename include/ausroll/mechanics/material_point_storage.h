/**
 * @file material_point_storage.h
 * Where the material points of the workpiece live: one MaterialPoint per cell quadrature point
 * of the locally owned cells. A header of its own so that io/ and adaptivity/ need not include
 * the assembler.
 */
#pragma once

#include <ausroll/material/material_point.h>

#include <deal.II/base/quadrature_point_data.h>
#include <deal.II/grid/tria.h>

namespace ausroll::mechanics
{
  /**
   * Storage of the material points of the locally owned cells (at Assembler::quadrature()).
   *
   * Invariant for every owner: whoever replaces or changes the material points other than
   * through an assembly (commit, restore, transfer to a new mesh, loading a checkpoint) must
   * increment the AssemblyCache::state of the assembler's cache. The cache keeps raw pointers
   * to the points (AssemblyCache::points) and reuses cell evaluations; both are valid only as
   * long as that counter has not moved (MechanicalSystem does this in its step and mesh
   * methods).
   */
  template <int dim>
  using MaterialPointStorage
      = dealii::CellDataStorage<typename dealii::Triangulation<dim>::cell_iterator,
                                material::MaterialPoint>;
} // namespace ausroll::mechanics
