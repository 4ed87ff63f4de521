/**
 * @file cone.h
 * Die shape `cone` (subsection `Contact/Die N/Cone`, 3D): an infinite circular cone, e.g. the
 * conical tip of a punch or a centre point.
 *
 * Canonical frame (frame_3d.h): apex at the origin, e3 = `Axis` pointing from the apex into the
 * cone (into the die material), e1 from `Reference direction`. The die material is the solid cone
 * {z >= 0, r <= z tan(alpha)} of half angle alpha (`Half angle`, 0 < alpha < 90 degrees). In the
 * meridian half plane (r, z) the surface is the ray rho d, rho >= 0, d = (sin alpha, cos alpha),
 * with the outward normal n = (cos alpha, -sin alpha): for a point (r, z) with rho = (r, z) . d
 * > 0 the closest surface point is rho d and the gap g = (r, z) . n (exact: the closest point of
 * a surface of revolution lies in the point's meridian half plane, and there the other ray
 * and the apex are not closer); for rho <= 0 it is the apex (a vertex: at_edge, n = x / |x|,
 * g = |x| > 0, such points are always outside).
 * - Surface coordinates (s, theta): s = -rho (the arc length in the direction of travel of the
 *   meridian, from the far side towards the apex; 0 at the apex), theta from e1.
 * - Curvatures: 0 along the generator, cos(alpha) / r_proj around the axis (convex).
 */
#pragma once

#include <ausroll/contact/rigid_surface.h>
#include <ausroll/contact/surfaces/frame_3d.h>
#include <ausroll/contact/surfaces/surface_factory.h>

#include <limits>

namespace ausroll::contact::surfaces
{
  /** An infinite circular cone, material inside (see the file documentation). */
  class Cone : public RigidSurface<3>
  {
  public:
    /**
     * Cone with apex @p apex, @p axis from the apex into the material (nonzero), half angle
     * @p half_angle in radians; @p reference fixes theta = 0 (zero: chosen). Throws
     * EntryError("Half angle", ...) unless 0 < half_angle < pi / 2.
     */
    Cone(const dealii::Point<3>     &apex,
         const dealii::Tensor<1, 3> &axis,
         double                      half_angle,
         const dealii::Tensor<1, 3> &reference = dealii::Tensor<1, 3>());

    std::string name() const override { return "cone"; }

    SurfaceProjection<3> project(const dealii::Point<3> &x,
                                 double                  max_distance
                                 = std::numeric_limits<double>::infinity()) const override;

    /** The closest point of the meridian ray to (r, z), r >= 0 (canonical meridian plane). */
    MeridianProjection project_meridian(double r, double z) const;

  private:
    Frame3D frame;
    double  sin_alpha, cos_alpha;
  };

  /** Subsection `Cone`. */
  struct ConeParameters : public ShapeParameters<3>
  {
    dealii::Point<3>     apex;             ///< `Apex`
    dealii::Tensor<1, 3> axis;             ///< `Axis` (from the apex into the die material)
    dealii::Tensor<1, 3> reference;        ///< `Reference direction` (theta = 0)
    double               half_angle = 45.; ///< `Half angle` alpha (degrees)

    /** Declare the entries of the subsection (the caller has entered it). */
    static void                            declare_parameters(dealii::ParameterHandler &prm);
    void                                   parse(dealii::ParameterHandler &prm,
                                                 const std::string        &path,
                                                 const std::string        &input_directory) override;
    std::unique_ptr<const RigidSurface<3>> create(const std::string &path) const override;
  };
} // namespace ausroll::contact::surfaces
