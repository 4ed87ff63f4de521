/**
 * @file curve_segment.h
 * One analytic segment of a 2D curve: a straight line, a circular arc or a piece of an involute,
 * with its exact closest point and bounding box. Chains of segments are CurveChain
 * (curve_chain.h), whose documentation states the conventions (direction of travel, normal,
 * curvature sign).
 */
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <cmath>
#include <limits>

namespace ausroll::geometry
{
  /**
   * One analytic segment of a 2D curve (a die surface, a profile): a straight line (possibly
   * extending to infinity at one or both ends), a circular arc, or a piece of an involute of a
   * circle. The segment has a direction of travel, which fixes its outward normal (material on the
   * right, see the file documentation of curve_chain.h). Along the segment a local arc-length
   * coordinate u runs from u_begin() (0 for every segment with a finite start) to u_end().
   */
  class CurveSegment
  {
  public:
    /** Kind of segment. */
    enum class Type
    {
      line,    ///< straight line segment, ray or infinite line
      arc,     ///< circular arc
      involute ///< piece of the involute of a circle
    };

    /** Straight segment from @p start to @p end (distinct points). */
    static CurveSegment line(const dealii::Point<2> &start, const dealii::Point<2> &end);

    /**
     * Straight line through @p reference with direction @p direction (normalized internally),
     * covering reference + u d for u in [@p u_begin, @p u_end]; either bound may be infinite
     * (-inf / +inf). u = 0 at @p reference.
     */
    static CurveSegment line_through(const dealii::Point<2>     &reference,
                                     const dealii::Tensor<1, 2> &direction,
                                     double                      u_begin,
                                     double                      u_end);

    /**
     * Circular arc with @p center and @p radius from polar angle @p start_angle over the signed
     * angle @p sweep (|sweep| <= 2 pi): sweep > 0 travels counter-clockwise (material outside the
     * circle, concave die, n towards the centre), sweep < 0 clockwise (material inside, convex
     * die, n radially outward).
     */
    static CurveSegment
    arc(const dealii::Point<2> &center, double radius, double start_angle, double sweep);

    /**
     * Involute of the base circle (@p base_center, @p base_radius r_b). With the tangent point
     * angle theta_T(u) = @p origin_angle + @p unwind_sense * u (unwind_sense = +1 or -1), the curve
     * point at roll angle u >= 0 is x(u) = c + r_b (e(theta_T) - unwind_sense u e_perp(theta_T)),
     * e(a) = (cos a, sin a), e_perp(a) = (-sin a, cos a). The segment is travelled from roll angle
     * @p roll_start to @p roll_end (either order; both >= 0). Arc length from the base circle is
     * r_b u^2 / 2, the radius of curvature r_b u.
     *
     * Example: the positive flank of a gear tooth whose axis is the +x axis (see
     * InvoluteGear) is involute(O, r_b, beta_0, -1, u_root, u_tip): travelled from root
     * to tip its normal points away from the tooth, the gear material is on the right.
     */
    static CurveSegment involute(const dealii::Point<2> &base_center,
                                 double                  base_radius,
                                 double                  origin_angle,
                                 int                     unwind_sense,
                                 double                  roll_start,
                                 double                  roll_end);

    /** The same curve travelled in the opposite direction (normal flipped). */
    CurveSegment reversed() const;

    /** Kind of segment. */
    Type type() const { return kind; }

    /** Local arc-length coordinate at the start (0, or -inf for a line infinite backwards). */
    double u_begin() const { return u_lo; }

    /** Local arc-length coordinate at the end (the length for a finite segment; may be +inf). */
    double u_end() const { return u_hi; }

    /** Length u_end() - u_begin() (may be infinite). */
    double length() const { return u_hi - u_lo; }

    /** Point at local coordinate @p u (clamped to [u_begin(), u_end()]). */
    dealii::Point<2> point(double u) const;

    /** Unit tangent (direction of travel) at local coordinate @p u (clamped). */
    dealii::Tensor<1, 2> tangent(double u) const;

    /** Outward unit normal n = tangent rotated by +90 degrees at local coordinate @p u. */
    dealii::Tensor<1, 2> normal(double u) const;

    /** Signed curvature (positive = convex die) at local coordinate @p u. */
    double curvature(double u) const;

    /** Start point (only for a finite start). */
    dealii::Point<2> start_point() const { return point(u_lo); }

    /** End point (only for a finite end). */
    dealii::Point<2> end_point() const { return point(u_hi); }

    /** The closest point of one segment (a step of CurveChain::project(), which turns it into a
        SurfaceProjection<2>). */
    struct ClosestPoint
    {
      /** Closest point of the segment. */
      dealii::Point<2> point;
      /** Its local coordinate u. */
      double u = 0.0;
      /** Squared distance from the query point. */
      double distance_squared = std::numeric_limits<double>::infinity();
      /**
       * True if the closest point is the start of the segment reached by clamping, i.e. x is not
       * on the segment's normal line there (x lies "before" the start).
       */
      bool at_start = false;
      /** True if the closest point is the end of the segment reached by clamping. */
      bool at_end = false;
    };

    /** Closest point of this segment to @p x (exact for all three segment types). */
    ClosestPoint closest_point(const dealii::Point<2> &x) const;

    /** True if the segment is finite (has a bounding box). */
    bool is_bounded() const { return std::isfinite(u_lo) && std::isfinite(u_hi); }

    /** Distance from @p x to the segment's axis-aligned bounding box (0 inside; 0 if unbounded). */
    double distance_to_bounding_box(const dealii::Point<2> &x) const;

    /** Lower-left corner of the bounding box (only for a bounded segment). */
    const dealii::Point<2> &bounding_box_min() const { return box_min; }

    /** Upper-right corner of the bounding box (only for a bounded segment). */
    const dealii::Point<2> &bounding_box_max() const { return box_max; }

  private:
    /** Set by the factories. */
    CurveSegment() = default;

    /** Compute #box_min and #box_max. */
    void compute_bounding_box();

    /** Roll angle of an involute at local coordinate @p u. */
    double roll_angle(double u) const;

    /** Local coordinate of an involute at roll angle @p roll. */
    double local_coordinate(double roll) const;

    /** Kind of segment. */
    Type kind = Type::line;
    /** Line: reference point (u = 0). Arc / involute: centre of the (base) circle. */
    dealii::Point<2> origin;
    /** Line: unit direction. */
    dealii::Tensor<1, 2> direction;
    /** Arc: radius; involute: base radius. */
    double radius = 0.0;
    /** Arc: start angle; involute: polar angle of the involute origin on the base circle. */
    double angle0 = 0.0;
    /** Arc: signed sweep; involute: unwind sense (+1 or -1). */
    double sweep = 0.0;
    /** Involute: roll angle at the start of travel. */
    double roll0 = 0.0;
    /** Involute: +1 if the roll angle increases along the direction of travel, else -1. */
    double roll_direction = 1.0;
    /** Local coordinate range. */
    double u_lo = 0.0, u_hi = 0.0;
    /** Axis-aligned bounding box. */
    dealii::Point<2> box_min, box_max;
  };
} // namespace ausroll::geometry
