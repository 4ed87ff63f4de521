/**
 * @file die_surface.h
 * Rigid die surfaces in 2D: a chain of analytic segments (straight lines, circular arcs, involute
 * flanks) given in the die's LOCAL frame, with closest-point projection, signed gap, normal,
 * tangent and curvilinear coordinate. This is the 2D chain engine; the shapes built from it
 * (contact/surfaces/: flat, circle, polyline, arc line, involute gear) reach the contact code as
 * a RigidSurface<2> through ChainSurface (end of this file).
 *
 * Conventions (hold for every segment and for the whole chain):
 * - The chain has a direction of travel; its unit tangent t points along it.
 * - The die material lies on the RIGHT of the direction of travel. The outward unit normal n
 *   points from the die INTO the space where the workpiece is: n = t rotated by +90 degrees,
 *   n = (-t_y, t_x); equivalently t = n rotated by -90 degrees, t = (n_y, -n_x).
 *   Examples: a flat die along +x has n = +y (workpiece above); a die roll (full circle with
 *   material inside) is travelled clockwise and has n radially outward.
 * - Signed gap g = (x - x_proj) . n: positive outside the die (open), negative = penetration.
 *   Wherever a projection is returned, x = x_proj + g n holds exactly (also at corners and ends).
 * - Curvilinear coordinate s: arc length along the chain from its start point (s = 0). A chain
 *   that starts with an infinite line has s = 0 at that line's reference point (s may be
 *   negative); a closed chain has s in [0, total_length()).
 * - Curvature: signed, positive for a convex die surface (centre of curvature inside the die
 *   material), negative for a concave one; 0 on lines and at corners.
 */
#pragma once

#include <ausroll/contact/rigid_surface.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace ausroll::geometry
{
  class InvoluteGear;
}

namespace ausroll::contact
{
  /**
   * One analytic segment of a die surface: a straight line (possibly extending to infinity at
   * one or both ends), a circular arc, or a piece of an involute of a circle. The segment has a
   * direction of travel, which fixes its outward normal (material on the right, see the file
   * documentation). Along the segment a local arc-length coordinate u runs from u_begin() (0 for
   * every segment with a finite start) to u_end().
   */
  class DieSegment
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
    static DieSegment line(const dealii::Point<2> &start, const dealii::Point<2> &end);

    /**
     * Straight line through @p reference with direction @p direction (normalized internally),
     * covering reference + u d for u in [@p u_begin, @p u_end]; either bound may be infinite
     * (-inf / +inf). u = 0 at @p reference.
     */
    static DieSegment line_through(const dealii::Point<2>     &reference,
                                   const dealii::Tensor<1, 2> &direction,
                                   double                      u_begin,
                                   double                      u_end);

    /**
     * Circular arc with @p center and @p radius from polar angle @p start_angle over the signed
     * angle @p sweep (|sweep| <= 2 pi): sweep > 0 travels counter-clockwise (material outside the
     * circle, concave die, n towards the centre), sweep < 0 clockwise (material inside, convex
     * die, n radially outward).
     */
    static DieSegment
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
     * geometry::InvoluteGear) is involute(O, r_b, beta_0, -1, u_root, u_tip): travelled from root
     * to tip its normal points away from the tooth, the gear material is on the right.
     */
    static DieSegment involute(const dealii::Point<2> &base_center,
                               double                  base_radius,
                               double                  origin_angle,
                               int                     unwind_sense,
                               double                  roll_start,
                               double                  roll_end);

    /** The same curve travelled in the opposite direction (normal flipped). */
    DieSegment reversed() const;

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

    /** Result of DieSegment::closest_point(). */
    struct LocalProjection
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
    LocalProjection closest_point(const dealii::Point<2> &x) const;

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
    DieSegment() = default;

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

  /**
   * Result of DieSurface::project() for a point x (all in the die's local frame).
   */
  struct Projection
  {
    /** False if no die point lies within the requested search distance (other fields unset). */
    bool valid = false;
    /** Closest point x_proj of the die surface. */
    dealii::Point<2> point;
    /** Signed gap g = (x - x_proj) . n: > 0 open, < 0 penetration. */
    double gap = 0.0;
    /** Distance |x - x_proj| = |g|. */
    double distance = 0.0;
    /**
     * Outward unit normal n (die -> workpiece). On the interior of a segment it is the segment
     * normal; at a corner or an open end it is +-(x - x_proj)/|x - x_proj| (the bisector of the
     * two segment normals if x is the corner itself).
     */
    dealii::Tensor<1, 2> normal;
    /** Unit tangent t = n rotated by -90 degrees (along the direction of travel). */
    dealii::Tensor<1, 2> tangent;
    /** Signed curvature at x_proj (positive = convex die; 0 at corners and on lines). */
    double curvature = 0.0;
    /** Curvilinear coordinate (arc length from the chain start) of x_proj. */
    double s = 0.0;
    /** Index of the segment holding x_proj (at a corner: the segment that was found closest; 0
        for a 2D shape that is not a DieSurface chain, seen through RigidDie::die_surface()). */
    unsigned int segment = 0;
    /**
     * True if x_proj is a joint between two segments (the normal is then +-(x - x_proj)/|x -
     * x_proj|, which at a tangent-continuous joint equals the segment normal).
     */
    bool at_corner = false;
    /** True if x_proj is the start or end point of an open chain. */
    bool at_end = false;
    /**
     * Arc length from x_proj to the nearer end of the die's outline (DieSurface::outline_margin()):
     * > 0 on the outline, 0 at its end, < 0 on an extension of an open chain beyond the given
     * points; +infinity on a closed chain or an unbounded one without given ends (a flat die).
     */
    double end_margin = std::numeric_limits<double>::infinity();
  };

  /**
   * A rigid die surface: a continuous chain of DieSegment s (open or closed) in the die's local
   * frame. See the file documentation for the orientation, gap and coordinate conventions.
   *
   * Projection (project()) returns the globally closest point of the chain. On a segment's
   * interior the normal is the segment normal; at a convex corner the normal is the direction from
   * the corner to the point; at a concave corner the segment giving the smaller distance wins (a
   * point exactly on the bisector takes the first); each point gets exactly one projection.
   * Open ends behave like convex corners (the point "wraps" around the end) and set
   * Projection::at_end so that a contact algorithm can release such points.
   *
   * Note: for an open chain "penetration" simply means "on the material side of the nearest
   * segment"; points far behind a short die, or beside an end on its material side, have a
   * negative gap. Use the search distance of project() to restrict the search to a band around
   * the surface, and Projection::end_margin to tell whether a point lies behind the die's outline
   * at all (a point whose projection is an end or lies on an extension is beyond the die).
   *
   * The outline of an open chain is the part between the points it was built from: the whole
   * chain, or, for a polyline or line-arc composite with extended ends, the chain without the two
   * rays to infinity (those keep the contact of a node that slides over an end smooth, but are no
   * part of the die's body). A flat die built infinite has no ends.
   */
  class DieSurface
  {
  public:
    /**
     * Die from a chain of @p segments, travelled in order; @p closed joins the last segment to the
     * first. Consecutive segments must join (to 1e-8 of the die size); only the first segment may
     * start at infinity and only the last may end there; a closed chain must be finite.
     * Throws ausroll::InputError otherwise.
     */
    DieSurface(std::vector<DieSegment> segments, bool closed);

    /**
     * Flat die through @p point with direction of travel @p direction, extending @p half_length
     * to each side of @p point (infinite by default). The workpiece side is to the left of
     * @p direction (n = direction rotated by +90 degrees); s = 0 at @p point for an infinite flat
     * and at point - half_length d for a finite one.
     */
    static DieSurface flat(const dealii::Point<2>     &point,
                           const dealii::Tensor<1, 2> &direction,
                           double half_length = std::numeric_limits<double>::infinity());

    /**
     * Full circle with @p center and @p radius, s = 0 at center + (radius, 0). With
     * @p material_inside (default; a die roll or round punch) it is travelled clockwise and the
     * normal points outward; otherwise (a round hole, concave) counter-clockwise with the normal
     * towards the centre.
     */
    static DieSurface
    circle(const dealii::Point<2> &center, double radius, bool material_inside = true);

    /**
     * Chain of straight segments through @p points (at least 2 distinct points; consecutive
     * duplicates are dropped). @p closed joins the last point to the first; @p extend_ends
     * (open chains only) extends the first and the last segment to infinity.
     */
    static DieSurface polyline(const std::vector<dealii::Point<2>> &points,
                               bool                                 closed = false,
                               bool                                 extend_ends = false);

    /**
     * Read a points file: plain text with two columns x y per line; everything after '#' is a
     * comment; blank lines are ignored. Throws ausroll::InputError (a std::runtime_error) naming
     * @p filename if the file cannot be read, a line is malformed, or it holds fewer than 2 points.
     */
    static std::vector<dealii::Point<2>> read_points_file(const std::string &filename);

    /** Open polyline die from a points file (see read_points_file() and polyline()). */
    static DieSurface polyline_from_file(const std::string &filename, bool extend_ends = false);

    /**
     * Line-arc composite: the polygon through the corner @p points with each corner rounded by a
     * tangent circular fillet (lines and tangent arcs alternate), e.g. a punch = 3 points and one
     * fillet radius. @p fillet_radii holds one radius per corner: points.size() - 2 values for an
     * open chain (interior corners), points.size() for a closed one, or a single value for all
     * corners; a radius of 0 keeps a sharp corner. Throws ausroll::InputError if the fillets of a
     * side do not fit on it.
     */
    static DieSurface arc_line_composite(const std::vector<dealii::Point<2>> &points,
                                         const std::vector<double>           &fillet_radii,
                                         bool                                 closed = false,
                                         bool                                 extend_ends = false);

    /**
     * Single involute flank die (see DieSegment::involute() for the parameters).
     */
    static DieSurface involute_flank(const dealii::Point<2> &base_center,
                                     double                  base_radius,
                                     double                  origin_angle,
                                     int                     unwind_sense,
                                     double                  roll_start,
                                     double                  roll_end);

    /**
     * External gear die with exact analytic flanks: root lands and tip lands (arcs), root fillets
     * (arcs), radial flank pieces below the base circle (lines) and involute flanks; gear centre
     * at the local origin, material inside (chain travelled clockwise).
     * With @p n_teeth = 0 (or the gear's number of teeth) the whole gear is built as a closed
     * chain with a tooth axis at polar angle @p tooth_axis_angle. Otherwise an open sector of
     * n_teeth teeth symmetric about @p tooth_axis_angle is built (tooth k at
     * tooth_axis_angle + ((n_teeth - 1)/2 - k) 2 pi/z), from the middle of the space before the
     * first tooth to the middle of the space after the last one.
     * With @p tip_round > 0 each tip corner is replaced by a circular arc of that radius tangent
     * to the involute flank and to the outside circle (centre at radius r_a - tip_round, at the
     * normal distance tip_round inside the flank: polar angle theta_h(r_a - tip_round) -
     * tip_round / r_b from the tooth axis); it must leave a tip land and meet the involute part.
     */
    static DieSurface involute_gear(const geometry::InvoluteGear &gear,
                                    double                        tooth_axis_angle = 0.0,
                                    unsigned int                  n_teeth = 0,
                                    double                        tip_round = 0.0);

    /** The same surface travelled backwards: normals flip, the die material changes side. */
    DieSurface reversed() const;

    /**
     * Closest point of the die to @p x (local frame), with gap, normal, tangent, curvature and
     * curvilinear coordinate. Segments whose bounding box is farther than @p max_distance are
     * skipped; if no die point lies within @p max_distance the result has valid == false.
     */
    Projection project(const dealii::Point<2> &x,
                       double max_distance = std::numeric_limits<double>::infinity()) const;

    /**
     * Point at curvilinear coordinate @p s: wrapped into [0, L) for a closed chain, clamped to the
     * chain for an open one.
     */
    dealii::Point<2> point_at(double s) const;

    /** Unit tangent at curvilinear coordinate @p s (as point_at()). */
    dealii::Tensor<1, 2> tangent_at(double s) const;

    /** Outward unit normal at curvilinear coordinate @p s (as point_at()). */
    dealii::Tensor<1, 2> normal_at(double s) const;

    /** Total arc length (infinite if the chain extends to infinity). */
    double total_length() const;

    /** Curvilinear coordinate of the chain start (0, or -inf for a chain starting at infinity). */
    double s_begin() const { return segment_s.front() + segs.front().u_begin(); }

    /** Curvilinear coordinate of the chain end. */
    double s_end() const { return segment_s.back() + segs.back().u_end(); }

    /** Whether the chain is closed. */
    bool is_closed() const { return closed; }

    /**
     * Arc length from curvilinear coordinate @p s to the nearer end of the outline (see the class
     * documentation): > 0 within it, < 0 beyond it; +infinity on a closed chain and towards an end
     * at infinity. @p count_start / @p count_end = false ignore that end (an end that is no edge
     * of the die's body, e.g. a profile end on the axis of revolution).
     */
    double outline_margin(double s, bool count_start = true, bool count_end = true) const;

    /** Curvilinear coordinates of the start and the end of the outline (+-infinity at infinity). */
    std::pair<double, double> outline() const { return {outline_begin, outline_end}; }

    /** Number of segments. */
    unsigned int n_segments() const { return static_cast<unsigned int>(segs.size()); }

    /** Segment @p i. */
    const DieSegment &segment(unsigned int i) const { return segs.at(i); }

    /** Curvilinear coordinate of the point u = 0 of segment @p i (s = segment_offset(i) + u). */
    double segment_offset(unsigned int i) const { return segment_s.at(i); }

  private:
    /** Index of the segment holding curvilinear coordinate @p s and the local coordinate. */
    std::pair<unsigned int, double> locate(double s) const;

    /** Make the outline run from the point @p first on the first segment to @p last on the last
        one (an open chain whose end segments extend beyond the points it was built from). */
    void set_outline(const dealii::Point<2> &first, const dealii::Point<2> &last);

    /** The segments in order of travel. */
    std::vector<DieSegment> segs;
    /** segment_s[i]: curvilinear coordinate of the point u = 0 of segment i. */
    std::vector<double> segment_s;
    /** Whether the last segment joins the first one. */
    bool closed;
    /** Length scale of the die (bounding box size) used for tolerances. */
    double scale;
    /** Curvilinear coordinates of the ends of the outline (s_begin(), s_end() unless set_outline()
        was called). */
    double outline_begin, outline_end;
  };
  /**
   * A DieSurface chain seen as a RigidSurface<2> (the interface the contact code uses): the
   * projection of the chain with s as the surface coordinate, at_corner as at_edge; closed
   * chains have the period total_length().
   */
  class ChainSurface : public RigidSurface<2>
  {
  public:
    /** The chain @p chain under the shape name @p name (as in the `Shape` selection). */
    ChainSurface(std::string name, DieSurface chain);

    std::string name() const override { return shape_name; }

    SurfaceProjection<2> project(const dealii::Point<2> &x,
                                 double                  max_distance
                                 = std::numeric_limits<double>::infinity()) const override;

    dealii::Point<2> point_at(const std::array<double, 1> &coordinates) const override;

    std::array<double, 1> coordinate_periods() const override;

    /** The chain of segments. */
    const DieSurface &chain() const { return die; }

  private:
    std::string shape_name;
    DieSurface  die;
  };
} // namespace ausroll::contact
