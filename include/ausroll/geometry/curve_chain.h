/**
 * @file curve_chain.h
 * 2D curves: a chain of analytic segments (straight lines, circular arcs, involute flanks,
 * curve_segment.h) with closest-point projection, signed gap, normal, tangent and curvilinear
 * coordinate. The 2D die shapes (contact/surfaces/: flat, circle, polyline, arc line, involute
 * gear; each builds its chain in its own file) reach the contact code as a RigidSurface<2>
 * through contact::surfaces::ChainSurface; the 3D profiles revolve or extrude a chain.
 *
 * Conventions (hold for every segment and for the whole chain):
 * - The chain has a direction of travel; its unit tangent t points along it.
 * - The material lies on the RIGHT of the direction of travel. The outward unit normal n
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

#include <ausroll/geometry/curve_segment.h>
#include <ausroll/geometry/surface_projection.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <limits>
#include <utility>
#include <vector>

namespace ausroll::geometry
{
  /**
   * A 2D curve (a rigid die surface, a profile): a continuous chain of CurveSegment s (open or
   * closed), in the die's local frame for a die. See the file documentation for the orientation,
   * gap and coordinate conventions.
   *
   * project() returns the globally closest point of the chain. On a segment's
   * interior the normal is the segment normal; at a convex corner the normal is the direction from
   * the corner to the point; at a concave corner the segment giving the smaller distance wins (a
   * point exactly on the bisector takes the first); each point gets exactly one projection.
   * Open ends behave like convex corners (the point "wraps" around the end) and set
   * SurfaceProjection::at_end so that a contact algorithm can release such points.
   *
   * Note: for an open chain "penetration" simply means "on the material side of the nearest
   * segment"; points far behind a short die, or beside an end on its material side, have a
   * negative gap. Use the search distance of project() to restrict the search to a band around
   * the surface, and SurfaceProjection::end_margin to tell whether a point lies behind the die's
   * outline at all (a point whose projection is an end or lies on an extension is beyond the die).
   *
   * The outline of an open chain is the part between the points it was built from: the whole
   * chain, or, for a polyline or line-arc composite with extended ends, the chain without the two
   * rays to infinity (those keep the contact of a node that slides over an end smooth, but are no
   * part of the die's body). A flat die built infinite has no ends.
   */
  class CurveChain
  {
  public:
    /**
     * Die from a chain of @p segments, travelled in order; @p closed joins the last segment to the
     * first. Consecutive segments must join (to 1e-8 of the die size); only the first segment may
     * start at infinity and only the last may end there; a closed chain must be finite.
     * Throws ausroll::InputError otherwise.
     */
    CurveChain(std::vector<CurveSegment> segments, bool closed);

    /** The same surface travelled backwards: normals flip, the die material changes side. */
    CurveChain reversed() const;

    /**
     * Closest point of the die to @p x (local frame), with gap, normal, tangent, curvature and
     * curvilinear coordinate (coordinates[0] = s; at_edge: at a joint of two segments). Segments
     * whose bounding box is farther than @p max_distance are skipped; if no die point lies within
     * @p max_distance the result has valid == false.
     */
    SurfaceProjection<2> project(const dealii::Point<2> &x,
                                 double                  max_distance
                                 = std::numeric_limits<double>::infinity()) const;

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
    const CurveSegment &segment(unsigned int i) const { return segs.at(i); }

    /** Index of the segment holding curvilinear coordinate @p s (wrapped or clamped as
        point_at(); at a joint the segment that starts there). */
    unsigned int segment_index(const double s) const { return locate(s).first; }

    /** Curvilinear coordinate of the point u = 0 of segment @p i (s = segment_offset(i) + u). */
    double segment_offset(unsigned int i) const { return segment_s.at(i); }

    /** Make the outline run from the point @p first on the first segment to @p last on the last
        one (an open chain whose end segments extend beyond the points it was built from: the
        polyline and arc-line builders with extended ends). */
    void set_outline(const dealii::Point<2> &first, const dealii::Point<2> &last);

  private:
    /** Index of the segment holding curvilinear coordinate @p s and the local coordinate. */
    std::pair<unsigned int, double> locate(double s) const;

    /** The segments in order of travel. */
    std::vector<CurveSegment> segs;
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
} // namespace ausroll::geometry
