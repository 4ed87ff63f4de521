/**
 * @file finite_cylinder.h
 * 3D rigid surface: a finite solid cylinder (a flat-faced roll die) with flat end faces and
 * optionally rounded rim edges.
 *
 * Conventions (in addition to rigid_surface.h and the surface-of-revolution block of
 * frame_3d.h): canonical frame (e1, e2, e3 = axis) at the centre; the die material is the solid
 * r <= R, |z| <= w/2 with the two rim edges rounded by a torus of profile radius r_e (0: sharp).
 * The meridian profile is travelled from the axis on the face z = +w/2 outwards, around the upper
 * rim, down the mantle r = R, around the lower rim and inwards on the face z = -w/2 to the axis:
 * - s = r on the upper face, s = (R - r_e) + r_e alpha on the upper rim (alpha the angle turned),
 *   s = (R - r_e) + pi r_e / 2 + (w/2 - r_e - z) on the mantle, and so on (total
 *   2 (R - r_e) + (w - 2 r_e) + pi r_e);
 * - t_1 along the profile: e_r on the upper face, -e3 on the mantle, -e_r on the lower face;
 *   t_2 = e_theta;
 * - curvatures: upper/lower face (0, 0); mantle (0, 1/R); rim (1/r_e, n_r / r); a sharp rim edge
 *   (r_e = 0) is an edge (at_edge, curvatures 0, normal +-(x - x_proj)/|x - x_proj|).
 * The projection is exact and closed-form for every point (the solid is convex: inside, the
 * nearer of the face and the mantle wins; a point on the axis takes theta = 0).
 */
#pragma once

#include <ausroll/contact/rigid_surface.h>
#include <ausroll/contact/surfaces/frame_3d.h>
#include <ausroll/contact/surfaces/surface_factory.h>

#include <deal.II/base/numbers.h>

namespace ausroll::contact::surfaces
{
  /** A finite solid cylinder with optional edge radius (see the file documentation). */
  class FiniteCylinder : public RigidSurface<3>
  {
  public:
    /**
     * Cylinder of @p radius R and @p width w along @p axis, centred at @p center (the mid-plane
     * of the width); rims rounded by @p edge_radius (0 <= r_e <= min(R, w/2)); @p reference fixes
     * theta = 0 (zero: chosen). Throws InputError for invalid sizes.
     */
    FiniteCylinder(const dealii::Point<3>     &center,
                   const dealii::Tensor<1, 3> &axis,
                   double                      radius,
                   double                      width,
                   double                      edge_radius = 0.,
                   const dealii::Tensor<1, 3> &reference = dealii::Tensor<1, 3>());

    std::string name() const override { return "cylinder"; }

    SurfaceProjection<3> project(const dealii::Point<3> &x,
                                 double                  max_distance
                                 = std::numeric_limits<double>::infinity()) const override;

    /** The surface point with coordinates (s, theta): s along the meridian profile (clamped to [0,
     * total length]), theta about the axis. */
    dealii::Point<3> point_at(const std::array<double, 2> &coordinates) const override;

    /** theta has the period 2 pi; s is not periodic. */
    std::array<double, 2> coordinate_periods() const override
    {
      return {{0., 2. * dealii::numbers::PI}};
    };

    /** The closest profile point to (r, z), r >= 0 (canonical meridian plane). */
    MeridianProjection project_meridian(double r, double z) const;

  private:
    Frame3D frame;
    double  R, h, re; ///< radius, half width, edge radius
  };

  /** Subsection `Cylinder` (FiniteCylinder). */
  struct CylinderParameters : public ShapeParameters<3>
  {
    dealii::Point<3>     center;           ///< `Center` (mid-plane of the width)
    dealii::Tensor<1, 3> axis;             ///< `Axis`
    dealii::Tensor<1, 3> reference;        ///< `Reference direction` (theta = 0)
    double               radius = 1.;      ///< `Radius`
    double               width = 1.;       ///< `Width`
    double               edge_radius = 0.; ///< `Edge radius`

    /** Declare the entries of the subsection (the caller has entered it). */
    static void                            declare_parameters(dealii::ParameterHandler &prm);
    void                                   parse(dealii::ParameterHandler &prm,
                                                 const std::string        &path,
                                                 const std::string        &input_directory) override;
    std::unique_ptr<const RigidSurface<3>> create(const std::string &path) const override;
  };
} // namespace ausroll::contact::surfaces
