/**
 * @file revolved_profile.h
 * 3D rigid surface: the surface of revolution of a 2D curve chain (geometry::CurveChain) about the
 * canonical z axis.
 *
 * Conventions (in addition to rigid_surface.h and the surface-of-revolution block of
 * frame_3d.h): the chain is given in the meridian half plane with 2D coordinates (r, z) (its
 * x coordinate is the distance from the axis, its y coordinate the axial position) and must lie
 * in r >= 0; its material side (on the right of the direction of travel) becomes the die
 * material. A point x is projected by the chain in its meridian plane, (r, z) =
 * (|x - (x . e3) e3|, x . e3), and the result rotated back (exact: the closest point of a surface
 * of revolution lies in the point's meridian half plane).
 * - Surface coordinates (s, theta): s the chain's curvilinear coordinate.
 * - A chain corner is an edge circle (at_edge); a chain end off the axis is a rim of an open
 *   surface (at_end, at_edge); a chain end on the axis is no boundary: it is smooth if the chain
 *   meets the axis at a right angle (a flat face through the axis), else a vertex (at_edge, e.g.
 *   the tip of a cone).
 * Example: the chain (0, w/2) -> (R, w/2) -> (R, -w/2) -> (0, -w/2) gives FiniteCylinder(R, w).
 */
#pragma once

#include <ausroll/contact/rigid_surface.h>
#include <ausroll/contact/surfaces/frame_3d.h>
#include <ausroll/contact/surfaces/profile_parameters.h>
#include <ausroll/contact/surfaces/surface_factory.h>
#include <ausroll/geometry/curve_chain.h>

namespace ausroll::contact::surfaces
{
  /** The surface of revolution of a 2D profile chain (see the file documentation). */
  class RevolvedProfile : public RigidSurface<3>
  {
  public:
    /**
     * Revolve @p profile (meridian coordinates (r, z), r >= 0) about @p axis through @p center;
     * @p reference fixes theta = 0 (zero: chosen). Throws EntryError("Profile/Points", ...) if the
     * chain reaches r < 0 (an infinite line must run parallel to the axis).
     */
    RevolvedProfile(const geometry::CurveChain &profile,
                    const dealii::Point<3>     &center = dealii::Point<3>(),
                    const dealii::Tensor<1, 3> &axis = dealii::Tensor<1, 3>({0., 0., 1.}),
                    const dealii::Tensor<1, 3> &reference = dealii::Tensor<1, 3>());

    std::string name() const override { return "revolved profile"; }

    SurfaceProjection<3> project(const dealii::Point<3> &x,
                                 double                  max_distance
                                 = std::numeric_limits<double>::infinity()) const override;

    /** The surface point with coordinates (s, theta): the profile point at s
     * (CurveChain::point_at(): wrapped on a closed profile, clamped on an open one) revolved by
     * theta. */
    dealii::Point<3> point_at(const std::array<double, 2> &coordinates) const override;

    /** theta has the period 2 pi; s that of a closed profile (0 for an open one). */
    std::array<double, 2> coordinate_periods() const override;

    /** The profile chain. */
    const geometry::CurveChain &profile() const { return chain; }

  private:
    geometry::CurveChain chain;
    Frame3D              frame;
    double               axis_tolerance; ///< a profile point with r below it lies on the axis
    /** Whether the start / the end of the profile's outline is a rim of the surface (not on the
        axis, not at infinity). */
    bool rim_at_start = false, rim_at_end = false;
  };

  /** Subsection `Revolved profile`. */
  struct RevolvedProfileParameters : public ShapeParameters<3>
  {
    dealii::Point<3>     center;    ///< `Center`
    dealii::Tensor<1, 3> axis;      ///< `Axis`
    dealii::Tensor<1, 3> reference; ///< `Reference direction` (theta = 0)
    ProfileParameters    profile;   ///< subsection `Profile`, coordinates (r, z)

    /** Declare the entries of the subsection (the caller has entered it). */
    static void                            declare_parameters(dealii::ParameterHandler &prm);
    void                                   parse(dealii::ParameterHandler &prm,
                                                 const std::string        &path,
                                                 const std::string        &input_directory) override;
    std::unique_ptr<const RigidSurface<3>> create(const std::string &path) const override;
  };
} // namespace ausroll::contact::surfaces
