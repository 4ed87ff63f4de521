/**
 * @file plane.h
 * 3D rigid surface: a plane (half-space die), infinite or a finite rectangle.
 *
 * Conventions (in addition to those of rigid_surface.h):
 * - The plane passes through `point` with the outward unit normal n (die material on the side
 *   -n, the workpiece on the side +n); gap g = (x - point) . n for an infinite plane.
 * - Tangents: t_1 = the given first tangent direction (its part orthogonal to n, normalised; by
 *   default Frame3D::perpendicular(n)), t_2 = n x t_1, so (t_1, t_2, n) is right-handed.
 * - Surface coordinates (xi_1, xi_2) = ((x_proj - point) . t_1, (x_proj - point) . t_2).
 * - Curvatures 0.
 * - Finite extent: |xi_1| <= half_length_1, |xi_2| <= half_length_2 (infinite by default). A point
 *   beyond the rectangle projects onto its boundary (at_end = at_edge = true), the normal is then
 *   +-(x - x_proj)/|x - x_proj| with the sign of the side of the plane (like an open end of a 2D
 *   chain: the contact algorithm may release such points).
 */
#pragma once

#include <ausroll/contact/rigid_surface.h>
#include <ausroll/contact/surfaces/frame_3d.h>
#include <ausroll/contact/surfaces/surface_factory.h>

#include <limits>

namespace ausroll::contact::surfaces
{
  /** A plane or a finite rectangle of a plane (see the file documentation). */
  class Plane : public RigidSurface<3>
  {
  public:
    /**
     * Plane through @p point with outward normal @p normal (nonzero, normalised internally) and
     * first tangent direction @p first_tangent (zero: chosen); half lengths of the rectangle
     * along t_1 and t_2 (> 0, infinite by default). Throws InputError for a zero normal or a
     * non-positive half length.
     */
    Plane(const dealii::Point<3>     &point,
          const dealii::Tensor<1, 3> &normal,
          const dealii::Tensor<1, 3> &first_tangent = dealii::Tensor<1, 3>(),
          double                      half_length_1 = std::numeric_limits<double>::infinity(),
          double                      half_length_2 = std::numeric_limits<double>::infinity());

    std::string name() const override { return "plane"; }

    SurfaceProjection<3> project(const dealii::Point<3> &x,
                                 double                  max_distance
                                 = std::numeric_limits<double>::infinity()) const override;

    /** The plane point with surface coordinates (xi_1, xi_2), clamped to the rectangle. */
    dealii::Point<3> point_at(const std::array<double, 2> &coordinates) const override;

    /** Not periodic: (0, 0). */
    std::array<double, 2> coordinate_periods() const override { return {{0., 0.}}; };

  private:
    /** e1 = t_1, e2 = t_2, e3 = n at the reference point. */
    Frame3D frame;
    /** Half lengths along t_1 and t_2. */
    double half[2];
  };

  /** Subsection `Plane`. */
  struct PlaneParameters : public ShapeParameters<3>
  {
    dealii::Point<3>     point;              ///< `Point`
    dealii::Tensor<1, 3> normal;             ///< `Normal` (outward, towards the workpiece)
    dealii::Tensor<1, 3> first_tangent;      ///< `First tangent` (zero: chosen)
    double               half_length_1 = 0.; ///< `Half length 1` (0: infinite)
    double               half_length_2 = 0.; ///< `Half length 2` (0: infinite)

    /** Declare the entries of the subsection (the caller has entered it). */
    static void                            declare_parameters(dealii::ParameterHandler &prm);
    void                                   parse(dealii::ParameterHandler &prm,
                                                 const std::string        &path,
                                                 const std::string        &input_directory) override;
    std::unique_ptr<const RigidSurface<3>> create(const std::string &path) const override;
  };
} // namespace ausroll::contact::surfaces
