/**
 * @file ellipse.h
 * Die shape `ellipse` (subsection `Contact/Die N/Ellipse`): an elliptic die (an oval roll or
 * punch, or an elliptic hole) with exact closest-point projection.
 */
#pragma once

#include <ausroll/contact/surfaces/surface_factory.h>

#include <deal.II/base/point.h>

#include <vector>

namespace ausroll::contact::surfaces
{
  /**
   * The ellipse x(phi) = c + R(alpha) (a cos phi, b sin phi) (R the rotation by alpha, phi the
   * parametric angle) as a closed rigid surface.
   *
   * Orientation as circle_chain(): with the material inside (an oval roll or punch) it is
   * travelled clockwise and the normal points out of the ellipse, curvature > 0; with the
   * material outside (a hole) counter-clockwise, the normal towards the centre, curvature < 0.
   * The surface coordinate is the arc length s from the end of the a axis, c + R(alpha)(a, 0),
   * in the direction of travel, in [0, L) (L the perimeter, the coordinate period). For a = b it
   * is circle_chain(c, a) rotated by alpha.
   *
   * Projection: by symmetry the point is reflected into the first quadrant of the ellipse's own
   * frame; the closest point there is x_i = e_i^2 y_i / (t + e_i^2) (e_0 >= e_1 the semi-axes,
   * y the point) with t the root of sum (e_i y_i / (t + e_i^2))^2 = 1 above -e_1^2 + e_1 y_1
   * (bracketed by that bound and 0 inside, |(e_0 y_0, e_1 y_1)| - e_1^2 outside): the function
   * decreases strictly there, so the root is found by bisection (of u = 1 + t/e_1^2, which keeps
   * its relative precision near the major axis) to the last bit, for any point
   * (near the centre, on the axes, far away); y_1 = 0 and y_0 = 0 are solved in closed form. Points
   * on the major axis inside the evolute (|y_0| < (e_0^2 - e_1^2)/e_0) have two closest points;
   * the one with the positive minor-axis coordinate is taken. The arc length is a
   * Gauss-Legendre table over the parametric angle (32 panels per unit of aspect ratio, at least
   * 64, 8 points each: relative error ~1e-15); a/b and b/a are limited to 1000.
   */
  class EllipseSurface : public RigidSurface<2>
  {
  public:
    /** Ellipse with @p center, semi-axes @p a, @p b, rotation @p alpha (radians, the a axis from
        +x counter-clockwise) and the die material inside or outside. InputError if invalid. */
    EllipseSurface(
        const dealii::Point<2> &center, double a, double b, double alpha, bool material_inside);

    std::string name() const override { return "ellipse"; }

    SurfaceProjection<2> project(const dealii::Point<2> &x,
                                 double                  max_distance
                                 = std::numeric_limits<double>::infinity()) const override;

    dealii::Point<2> point_at(const std::array<double, 1> &coordinates) const override;

    std::array<double, 1> coordinate_periods() const override { return {{perimeter}}; }

    /** Perimeter L. */
    double total_length() const { return perimeter; }

    /** Arc length from phi = 0 counter-clockwise to the parametric angle @p phi in [0, 2 pi]. */
    double arc_length(double phi) const;

  private:
    /** |dx/dphi| = sqrt(a^2 sin^2 phi + b^2 cos^2 phi). */
    double speed(double phi) const;

    /** Parametric angle in [0, 2 pi) with arc_length(phi) = @p length (in [0, L)). */
    double angle_at_length(double length) const;

    /** Surface coordinate s of parametric angle @p phi. */
    double coordinate(double phi) const;

    dealii::Point<2>    c;
    double              a, b;
    double              cos_alpha, sin_alpha;
    bool                inside;
    double              panel_width;
    std::vector<double> cumulative; ///< arc length at panel boundaries k * panel_width
    double              perimeter;
  };

  /**
   * Subsection `Ellipse`: `Center`, `Semi-axis a` along the direction `Rotation angle`,
   * `Semi-axis b` across it, `Material inside` (see EllipseSurface).
   */
  struct EllipseParameters : public ShapeParameters<2>
  {
    dealii::Point<2> center{0., 0.};         ///< `Center`
    double           semi_axis_a = 1.;       ///< `Semi-axis a` (mm)
    double           semi_axis_b = 1.;       ///< `Semi-axis b` (mm)
    double           rotation_angle = 0.;    ///< `Rotation angle` of the a axis (degrees)
    bool             material_inside = true; ///< `Material inside`

    /** Declare the entries of subsection `Ellipse` (the caller has entered it). */
    static void                            declare_parameters(dealii::ParameterHandler &prm);
    void                                   parse(dealii::ParameterHandler &prm,
                                                 const std::string        &path,
                                                 const std::string        &input_directory) override;
    std::unique_ptr<const RigidSurface<2>> create(const std::string &path) const override;
  };
} // namespace ausroll::contact::surfaces
