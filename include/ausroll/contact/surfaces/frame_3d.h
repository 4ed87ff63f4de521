/**
 * @file frame_3d.h
 * Helpers shared by the 3D rigid surfaces (contact/surfaces/plane.h, finite_cylinder.h, torus.h,
 * revolved_profile.h, extruded_profile.h): a right-handed orthonormal frame that places a shape's
 * canonical coordinates in the die's local frame, and the lifting of a meridian-plane (r, z)
 * projection to 3D for surfaces of revolution about the canonical z axis.
 *
 * Conventions of the surfaces of revolution (FiniteCylinder, Torus, RevolvedProfile), in the
 * shape's canonical frame (e1, e2, e3 = axis) with cylindrical coordinates (r, theta, z),
 * x = r (cos theta e1 + sin theta e2) + z e3:
 * - The meridian profile lives in the half plane (r >= 0, z); its 2D normal (n_r, n_z) and
 *   direction of travel t_m = (n_z, -n_r) follow the geometry::CurveChain convention (material on
 * the right).
 * - n = n_r e_r + n_z e3; t_1 = t_m,r e_r + t_m,z e3 (along the profile, direction of travel);
 *   t_2 = e_theta = e3 x e_r (circumferential); then t_1 x t_2 = n.
 * - Surface coordinates (s, theta): s the arc length along the profile, theta in (-pi, pi] from e1.
 * - Curvatures: kappa_1 = the profile's curvature (positive convex), kappa_2 = n_r / r_proj (the
 *   circumferential normal curvature, Meusnier), = kappa_1 on the axis; both 0 at an edge.
 * - A point on the axis (r = 0) has no meridian plane: theta = 0 (e_r = e1) is used, so the
 *   projection is one of the equally close points of a circle.
 */
#pragma once

#include <ausroll/contact/rigid_surface.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

namespace ausroll::contact::surfaces
{
  /**
   * A right-handed orthonormal frame (e1, e2, e3) at an origin: canonical coordinates xi of a shape
   * map to x = origin + xi_0 e1 + xi_1 e2 + xi_2 e3 in the die's local frame.
   */
  class Frame3D
  {
  public:
    /** The identity frame (origin 0, e1 = x, e2 = y, e3 = z). */
    Frame3D();

    /**
     * Frame at @p origin with e3 = @p axis / |axis| (nonzero) and e1 = the part of @p reference
     * orthogonal to e3, normalised; if @p reference is zero or (nearly) parallel to the axis, e1 is
     * perpendicular() of e3. e2 = e3 x e1.
     */
    Frame3D(const dealii::Point<3>     &origin,
            const dealii::Tensor<1, 3> &axis,
            const dealii::Tensor<1, 3> &reference = dealii::Tensor<1, 3>());

    /** Canonical coordinates of the local point @p x. */
    dealii::Point<3> to_canonical(const dealii::Point<3> &x) const;

    /** Local point of the canonical coordinates @p xi. */
    dealii::Point<3> to_local(const dealii::Point<3> &xi) const;

    /** Canonical vector -> local vector. */
    dealii::Tensor<1, 3> vector_to_local(const dealii::Tensor<1, 3> &v) const;

    /** Map a projection computed in canonical coordinates to the local frame (in place). */
    void to_local(SurfaceProjection<3> &p) const;

    /** Basis vector e_i (i = 0, 1, 2) in the local frame. */
    const dealii::Tensor<1, 3> &basis(const unsigned int i) const { return e[i]; }

    /** Origin in the local frame. */
    const dealii::Point<3> &origin() const { return o; }

    /**
     * A unit vector orthogonal to the unit vector @p n, chosen deterministically: the coordinate
     * axis least aligned with @p n made orthogonal to it (e.g. e_x for n = e_z).
     */
    static dealii::Tensor<1, 3> perpendicular(const dealii::Tensor<1, 3> &n);

  private:
    dealii::Point<3>     o;
    dealii::Tensor<1, 3> e[3];
  };

  /** A projection onto a meridian profile in the (r, z) half plane (see the file documentation). */
  struct MeridianProjection
  {
    dealii::Point<2>     point;           ///< closest profile point (r, z)
    dealii::Tensor<1, 2> normal;          ///< outward unit normal (n_r, n_z)
    double               gap = 0.;        ///< signed gap in the meridian plane
    double               curvature = 0.;  ///< profile curvature (positive convex)
    double               s = 0.;          ///< arc length along the profile
    bool                 at_edge = false; ///< corner of the profile (an edge circle in 3D)
    bool                 at_end = false;  ///< open end of the profile (a rim of the surface)
    /** Arc length to the nearer rim along the profile (SurfaceProjection::end_margin). */
    double end_margin = std::numeric_limits<double>::infinity();
  };

  /**
   * The 3D projection (canonical coordinates) of the canonical point @p x onto the surface of
   * revolution of a profile, given the projection @p m of x's meridian coordinates
   * (r = |x - (x . e3) e3|, z = x . e3). @p axis_tolerance: a profile point with r below it lies on
   * the axis (circumferential curvature = profile curvature). An end of the profile on the axis
   * is no rim of the surface: the caller clears MeridianProjection::at_end there.
   */
  SurfaceProjection<3> revolve_meridian_projection(const dealii::Point<3>   &x,
                                                   const MeridianProjection &m,
                                                   double                    axis_tolerance);
} // namespace ausroll::contact::surfaces
