/**
 * @file distortion_check.h
 * Detection of a folding mesh from the volume change J = det F at the quadrature points of a
 * converged state (`Loading/Volume change limit`).
 */
#pragma once

#include <ausroll/mechanics/planar_kinematics.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/point.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/trilinos_vector.h>

#include <limits>
#include <string>

namespace ausroll::mechanics
{
  /**
   * Range of the volume change J = det F over the quadrature points of a state, with the points
   * (reference coordinates) where the extremes lie (same on all ranks). Plastic flow is isochoric
   * and the elastic volume change of metals is below 1 %, so J far from 1 at a point means that
   * the element is folding, not that the material is compressed (F-bar leaves the pointwise J
   * free and only the cell mean physical).
   */
  template <int dim>
  struct VolumeChangeRange
  {
    double             min_J = std::numeric_limits<double>::max(); ///< smallest J
    double             max_J = 0.;                                 ///< largest J
    dealii::Point<dim> where_min;                                  ///< where J is smallest
    dealii::Point<dim> where_max;                                  ///< where J is largest
  };

  /** The range of J = det F at the points of @p quadrature for the displacement @p u (ghosted);
      collective. */
  template <int dim>
  VolumeChangeRange<dim> volume_change_range(const dealii::Mapping<dim>    &mapping,
                                             const dealii::DoFHandler<dim> &dof_handler,
                                             const dealii::Quadrature<dim> &quadrature,
                                             const PlanarKinematics<dim>   &kinematics,
                                             const dealii::TrilinosWrappers::MPI::Vector &u);

  /**
   * The warning for a folding mesh if J of @p range leaves [@p limit, 1 / @p limit] in step
   * @p step at time @p time (names the point, the step and the entries that help), else "".
   */
  template <int dim>
  std::string distortion_warning(const VolumeChangeRange<dim> &range,
                                 const double                  limit,
                                 const unsigned int            step,
                                 const double                  time);

  /**
   * Watches the converged states of a run for a folding mesh (`Loading/Volume change limit`):
   * check() reports the first state whose J leaves [limit, 1 / limit]; later states are not
   * checked (the warning stands).
   */
  template <int dim>
  class DistortionMonitor
  {
  public:
    /** Monitor with @p limit (<= 0: off). */
    explicit DistortionMonitor(const double limit)
        : limit(limit)
    {
    }

    /**
     * Check the state @p u (ghosted) of step @p step at @p time (the range of J goes to
     * @p detail_log); returns true if this is the first state that folds (see warning()).
     */
    bool check(const dealii::Mapping<dim>                  &mapping,
               const dealii::DoFHandler<dim>               &dof_handler,
               const dealii::Quadrature<dim>               &quadrature,
               const PlanarKinematics<dim>                 &kinematics,
               const dealii::TrilinosWrappers::MPI::Vector &u,
               const unsigned int                           step,
               const double                                 time,
               dealii::ConditionalOStream                  &detail_log);

    /** The warning of the first folding state (distortion_warning()), "" while none. */
    const std::string &warning() const { return first_warning; }

  private:
    double      limit;
    std::string first_warning;
  };
} // namespace ausroll::mechanics
