/**
 * @file prescribed.h
 * Die motion `prescribed` (subsection `Contact/Die N/Motion/Prescribed`): translation u(t) and
 * rotation phi(t) about a pivot.
 */
#pragma once

#include <ausroll/contact/die_motion.h>

#include <memory>
#include <string>

namespace ausroll::contact
{
  /**
   * Prescribed translation u(t) and rotation phi(t) about a pivot (3D: about an axis through the
   * pivot):
   *
   *     x(t) = p0 + u(t) + R(phi(t)) (X - P),
   *
   * with P the pivot in local coordinates and p0 its global position when u = 0 (by default
   * p0 = P: the local frame coincides with the global one at rest). Both functions are supplied
   * by the caller (e.g. from a load curve); an empty function counts as zero.
   */
  template <int dim>
  class PrescribedMotion : public DieMotion<dim>
  {
  public:
    /**
     * Motion with @p translation u(t) and @p rotation phi(t) (rad, counter-clockwise) about the
     * @p pivot P (local coordinates), whose rest position p0 equals P.
     */
    PrescribedMotion(VectorTimeFunction<dim>   translation,
                     TimeFunction              rotation,
                     const dealii::Point<dim> &pivot = dealii::Point<dim>());

    /**
     * As above, with the pivot at global position @p pivot_rest_position when u = 0, rotating
     * about @p axis (3D; zero: e_z; ignored in 2D).
     */
    PrescribedMotion(VectorTimeFunction<dim>       translation,
                     TimeFunction                  rotation,
                     const dealii::Point<dim>     &pivot,
                     const dealii::Point<dim>     &pivot_rest_position,
                     const dealii::Tensor<1, dim> &axis = dealii::Tensor<1, dim>());

    /** Translation with constant @p velocity from the rest position (u = v t), no rotation. */
    static PrescribedMotion constant_velocity(const dealii::Tensor<1, dim> &velocity);

    /** Pose: c = p0 + u(t), theta = phi(t) about the axis, X_ref = P. */
    DiePose<dim> pose(double t) const override;

  private:
    /** u(t). */
    VectorTimeFunction<dim> translation;
    /** phi(t). */
    TimeFunction rotation;
    /** Pivot P in local coordinates. */
    dealii::Point<dim> pivot;
    /** Global position p0 of the pivot at rest. */
    dealii::Point<dim> pivot_rest;
    /** Rotation axis (3D). */
    dealii::Tensor<1, dim> axis;
  };

  /** Subsection `Motion/Prescribed` (`Motion/Type = prescribed`). */
  struct PrescribedMotionParameters : public MotionParameters
  {
    std::string translation = "0; 0"; ///< `Translation` u(t) (mm), one expression per component
    std::string rotation = "0";       ///< `Rotation` phi(t) (degrees)
    std::string pivot = "0, 0";       ///< `Pivot` (die-local rotation centre; read by create())
    std::string axis = "0, 0, 1";     ///< `Axis` of the rotation (3D; read by create_3d())

    /** Declare the entries of subsection `Prescribed` (the caller has entered it). */
    static void                   declare_parameters(dealii::ParameterHandler &prm);
    void                          parse(dealii::ParameterHandler &prm,
                                        const std::string        &path,
                                        const std::string        &input_directory) override;
    std::unique_ptr<DieMotion<2>> create_2d(const std::string &path) const override;
    std::unique_ptr<DieMotion<3>> create_3d(const std::string &path) const override;
  };
} // namespace ausroll::contact
