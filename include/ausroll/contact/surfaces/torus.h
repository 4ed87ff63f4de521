/**
 * @file torus.h
 * 3D rigid surface: a ring torus (the round-faced disk die: a roll of radius R whose face has the
 * profile radius rho), die material inside the tube.
 *
 * Conventions (in addition to rigid_surface.h and the surface-of-revolution block of
 * frame_3d.h): canonical frame (e1, e2, e3 = axis) at the centre; the tube is the set
 * (r - R)^2 + z^2 <= rho^2, 0 < rho < R. The meridian profile is the circle of centre (R, 0) and
 * radius rho travelled clockwise (as circle_chain()): with phi the polar angle of the normal
 * in the (r, z) plane, n = cos phi e_r + sin phi e3,
 * - s = rho (-phi) wrapped into [0, 2 pi rho): s = 0 at the outermost circle r = R + rho, then
 *   downwards (t_1 = sin phi e_r - cos phi e3; t_2 = e_theta);
 * - curvatures (1 / rho, cos phi / (R + rho cos phi)): positive on the outer half (the die face),
 *   negative on the inner half (a saddle).
 * The projection is exact and closed-form: the closest point lies in x's meridian plane on the
 * ray from the tube centre (R, 0) through (r, z). A point on the tube's centre circle takes
 * phi = 0, a point on the axis theta = 0. Note that the die material is the tube only: points near
 * the axis are outside it (a solid roll with a round face is a RevolvedProfile).
 */
#pragma once

#include <ausroll/contact/rigid_surface.h>
#include <ausroll/contact/surfaces/frame_3d.h>
#include <ausroll/contact/surfaces/surface_factory.h>

#include <deal.II/base/numbers.h>

namespace ausroll::contact::surfaces
{
  /** A ring torus, material inside the tube (see the file documentation). */
  class Torus : public RigidSurface<3>
  {
  public:
    /**
     * Torus of major radius @p major_radius R and minor (profile) radius @p minor_radius rho
     * (0 < rho < R) about @p axis through @p center; @p reference fixes theta = 0 (zero: chosen).
     * Throws EntryError ("Major radius", "Minor radius") for invalid sizes.
     */
    Torus(const dealii::Point<3>     &center,
          const dealii::Tensor<1, 3> &axis,
          double                      major_radius,
          double                      minor_radius,
          const dealii::Tensor<1, 3> &reference = dealii::Tensor<1, 3>());

    std::string name() const override { return "torus"; }

    SurfaceProjection<3> project(const dealii::Point<3> &x,
                                 double                  max_distance
                                 = std::numeric_limits<double>::infinity()) const override;

    /** The surface point with coordinates (s, theta) (s wrapped into [0, 2 pi rho)). */
    dealii::Point<3> point_at(const std::array<double, 2> &coordinates) const override;

    /** Both periodic: (2 pi rho, 2 pi). */
    std::array<double, 2> coordinate_periods() const override
    {
      return {{2. * dealii::numbers::PI * rho, 2. * dealii::numbers::PI}};
    };

    /** The closest profile point to (r, z), r >= 0 (canonical meridian plane). */
    MeridianProjection project_meridian(double r, double z) const;

  private:
    Frame3D frame;
    double  R, rho;
  };

  /** Subsection `Torus`. */
  struct TorusParameters : public ShapeParameters<3>
  {
    dealii::Point<3>     center;            ///< `Center`
    dealii::Tensor<1, 3> axis;              ///< `Axis`
    dealii::Tensor<1, 3> reference;         ///< `Reference direction` (theta = 0)
    double               major_radius = 2.; ///< `Major radius` R
    double               minor_radius = 1.; ///< `Minor radius` rho (face profile radius)

    /** Declare the entries of the subsection (the caller has entered it). */
    static void                            declare_parameters(dealii::ParameterHandler &prm);
    void                                   parse(dealii::ParameterHandler &prm,
                                                 const std::string        &path,
                                                 const std::string        &input_directory) override;
    std::unique_ptr<const RigidSurface<3>> create(const std::string &path) const override;
  };
} // namespace ausroll::contact::surfaces
