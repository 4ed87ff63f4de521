/**
 * @file refinement_indicators.h
 * Where to refine and coarsen: Kelly, contact band, plastic strain (`Adaptivity/Indicators`).
 */
#pragma once

#include <ausroll/adaptivity/adaptivity_parameters.h>
#include <ausroll/mechanics/material_point_storage.h>

#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/trilinos_vector.h>

#include <functional>

namespace ausroll::adaptivity
{
  /** Distance of a (deformed) point to the nearest die, at the current and the next step. */
  template <int dim>
  using DieDistance = std::function<double(const dealii::Point<dim> &)>;

  /**
   * Set refine and coarsen flags on the locally owned cells of @p triangulation from the
   * indicators selected in @p parameters, then apply the level and size limits. A cell is flagged
   * for refinement if any indicator wants it; for coarsening only if all allow it.
   *  - Kelly: KellyErrorEstimator of the displacement, fixed fractions.
   *  - contact: the deformed cell centre is closer than `Contact band` plus half the cell size to a
   *    die (@p die_distance covers the present and the next die position); coarsening allowed
   *    beyond twice that (or beyond `Coarsening distance` plus the cell size if that is set). With
   * `Fine contact band` > 0 the band is graded: cells farther than that (plus half their size) are
   * refined at most to `Maximum level` - 1 (whichever indicator asks), and cells on `Maximum level`
   * beyond twice it plus their size are coarsened to that level.
   *  - plastic strain: max - min of the equivalent plastic strain over the cell's points, fixed
   *    fractions (marks the elastic-plastic front and strong gradients).
   *  - `Keep plastic strain above` > 0: no cell with a point above that equivalent plastic strain
   *    is coarsened; with `Plastic coarsening level` >= 0 such a cell is coarsened where the
   *    indicators allow it, but not below that level (the plastic groove behind a die is kept at
   *    an intermediate level instead of the finest one).
   * Returns true if any cell (on any rank) is flagged.
   */
  template <int dim>
  bool mark_cells(const AdaptivityParameters                        &parameters,
                  dealii::parallel::distributed::Triangulation<dim> &triangulation,
                  const dealii::Mapping<dim>                        &mapping,
                  const dealii::DoFHandler<dim>                     &dof_handler,
                  const dealii::TrilinosWrappers::MPI::Vector       &solution,
                  const mechanics::MaterialPointStorage<dim>        &material_points,
                  const DieDistance<dim>                            &die_distance);
} // namespace ausroll::adaptivity
