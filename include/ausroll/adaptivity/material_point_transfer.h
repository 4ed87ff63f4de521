/**
 * @file material_point_transfer.h
 * Moving material-point state across mesh refinement, coarsening and repartitioning (and to and
 * from checkpoint files).
 */
#pragma once

#include <ausroll/mechanics/material_point_storage.h>
#include <ausroll/mechanics/quadrature_interpolation.h>

#include <deal.II/base/quadrature.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/lac/full_matrix.h>

#include <functional>
#include <vector>

namespace ausroll::adaptivity
{
  /** How states move between parent and child cells (`Adaptivity/State transfer`). */
  enum class TransferMethod
  {
    /** Refinement: Lagrange interpolation through the parent's Gauss points; coarsening:
        least-squares fit of the children's points by the parent's polynomial. Followed by the
        projection of each state onto the yield surface where it would lie outside. */
    polynomial,
    /** Refinement: nearest parent point; coarsening: average of the child holding the point.
        Convex combinations only: admissible without projection, but more diffusive. */
    nearest_point
  };

  /**
   * Transfers the committed MaterialState of every quadrature point with the cells of a
   * parallel::distributed::Triangulation. deal.II 9.4's ContinuousQuadratureDataTransfer does not
   * coarsen and its projection overshoots plastic fields; this transfer works cell by cell between
   * parents and children and never leaves a state outside the yield surface (polynomial values are
   * projected back by @p make_admissible; nearest-point values are convex combinations of
   * admissible states). The same packing serves checkpoints (save/load: every cell persists).
   *
   * Use: prepare() before Triangulation::execute_coarsening_and_refinement() (or save()), then
   * unpack() after it (or after load()): unpack() re-initialises the storage on the new locally
   * owned cells and fills it.
   */
  template <int dim>
  class MaterialPointTransfer
  {
  public:
    /**
     * Transfer for material points at the points of @p quadrature (a QGauss rule) with
     * @p method; @p make_admissible projects a state onto its yield surface (may be empty).
     */
    MaterialPointTransfer(dealii::parallel::distributed::Triangulation<dim> &triangulation,
                          mechanics::MaterialPointStorage<dim>              &storage,
                          const dealii::Quadrature<dim>                     &quadrature,
                          const TransferMethod                               method,
                          std::function<void(material::MaterialState &)>     make_admissible);

    /** Register the packing callback (before the mesh changes). */
    void prepare();

    /** Re-create the storage on the new cells and fill it (after the mesh changed). */
    void unpack();

  private:
    /** The packed committed states of the points of @p cell (children restricted if coarsening). */
    std::vector<char> pack(const typename dealii::Triangulation<dim>::cell_iterator &cell,
                           const typename dealii::Triangulation<dim>::CellStatus     status) const;

    /** State of child point @p q of child @p c from the parent's packed point values. */
    material::MaterialState child_state(const std::vector<double> &parent_values,
                                        const unsigned int         c,
                                        const unsigned int         q) const;

    dealii::parallel::distributed::Triangulation<dim> &triangulation;
    mechanics::MaterialPointStorage<dim>              &storage;
    const dealii::Quadrature<dim>                      quadrature;
    const TransferMethod                               method;
    std::function<void(material::MaterialState &)>     make_admissible;
    unsigned int handle = dealii::numbers::invalid_unsigned_int;

    /** prolongation[c](q, p): weight of parent point p at point q of child c. */
    std::vector<dealii::FullMatrix<double>> prolongation;
    /** restriction(q, c * n_q + k): weight of point k of child c at parent point q. */
    dealii::FullMatrix<double> restriction;
  };
} // namespace ausroll::adaptivity
