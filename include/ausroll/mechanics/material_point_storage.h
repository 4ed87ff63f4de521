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
  /** Storage of the material points of the locally owned cells (at Assembler::quadrature()). */
  template <int dim>
  using MaterialPointStorage
      = dealii::CellDataStorage<typename dealii::Triangulation<dim>::cell_iterator,
                                material::MaterialPoint>;
} // namespace ausroll::mechanics
