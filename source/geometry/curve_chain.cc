/**
 * @file curve_chain.cc
 * The chains of 2D curve segments (see curve_chain.h for the conventions).
 */
#include <ausroll/core/exceptions.h>
#include <ausroll/geometry/curve_chain.h>
#include <ausroll/geometry/plane_vectors.h>

#include <algorithm>
#include <sstream>

namespace ausroll::geometry
{
  using dealii::Point;
  using dealii::Tensor;
  using namespace plane;

  // ------------------------------------------------------------------ CurveChain

  CurveChain::CurveChain(std::vector<CurveSegment> segments, const bool closed)
      : segs(std::move(segments))
      , closed(closed)
      , scale(0.0)
      , outline_begin(0.0)
      , outline_end(0.0)
  {
    require(!segs.empty(), plane::curve_entry, "a die surface needs at least one segment");
    const std::size_t n = segs.size();
    for (std::size_t i = 0; i < n; ++i)
    {
      require(std::isfinite(segs[i].u_begin()) || (i == 0 && !closed),
              plane::curve_entry,
              "only the first segment of an open chain may start at infinity");
      require(std::isfinite(segs[i].u_end()) || (i + 1 == n && !closed),
              plane::curve_entry,
              "only the last segment of an open chain may end at infinity");
    }

    // Size of the die for tolerances: bounding box of all finite points.
    std::vector<Point<2>> corners;
    for (const CurveSegment &seg : segs)
      if (seg.is_bounded())
      {
        corners.push_back(seg.bounding_box_min());
        corners.push_back(seg.bounding_box_max());
      }
      else
        corners.push_back(seg.point(0.0));
    Point<2> lo = corners.front(), hi = corners.front();
    for (const Point<2> &p : corners)
      for (unsigned int d = 0; d < 2; ++d)
      {
        lo[d] = std::min(lo[d], p[d]);
        hi[d] = std::max(hi[d], p[d]);
      }
    scale = std::max(lo.distance(hi), 1e-300);
    for (const CurveSegment &seg : segs)
      if (seg.is_bounded())
        scale = std::max(scale, seg.length());

    const double tol = 1e-8 * scale;
    for (std::size_t i = 0; i + 1 < n + (closed ? 1 : 0); ++i)
    {
      const CurveSegment &a = segs[i], &b = segs[(i + 1) % n];
      if (a.end_point().distance(b.start_point()) > tol)
      {
        std::ostringstream msg;
        msg << "segment " << i << " ends at (" << a.end_point() << ") but segment " << (i + 1) % n
            << " starts at (" << b.start_point() << ")";
        throw InputError(plane::curve_entry + ": " + msg.str());
      }
    }

    segment_s.resize(n, 0.0);
    for (std::size_t i = 0; i + 1 < n; ++i)
      segment_s[i + 1] = segment_s[i] + segs[i].u_end();
    outline_begin = s_begin();
    outline_end = s_end();
  }

  void CurveChain::set_outline(const Point<2> &first, const Point<2> &last)
  {
    outline_begin = segment_s.front() + segs.front().closest_point(first).u;
    outline_end = segment_s.back() + segs.back().closest_point(last).u;
  }

  double
  CurveChain::outline_margin(const double s, const bool count_start, const bool count_end) const
  {
    double margin = inf;
    if (closed)
      return margin;
    if (count_start)
      margin = std::min(margin, s - outline_begin);
    if (count_end)
      margin = std::min(margin, outline_end - s);
    return margin;
  }

  CurveChain CurveChain::reversed() const
  {
    std::vector<CurveSegment> r;
    r.reserve(segs.size());
    for (auto it = segs.rbegin(); it != segs.rend(); ++it)
      r.push_back(it->reversed());
    CurveChain result(std::move(r), closed);
    if (!closed && (outline_begin != s_begin() || outline_end != s_end()))
      result.set_outline(point_at(outline_end), point_at(outline_begin));
    return result;
  }

  double CurveChain::total_length() const
  {
    return s_end() - s_begin();
  }

  std::pair<unsigned int, double> CurveChain::locate(double s) const
  {
    if (closed)
      s = positive_modulo(s, total_length());
    else
      s = std::max(s_begin(), std::min(s_end(), s));
    // Segment i (i >= 1) starts at segment_s[i]; take the last one starting at or before s.
    const auto         it = std::upper_bound(segment_s.begin() + 1, segment_s.end(), s);
    const unsigned int i = static_cast<unsigned int>(it - segment_s.begin()) - 1;
    return {i, s - segment_s[i]};
  }

  Point<2> CurveChain::point_at(const double s) const
  {
    const auto [i, u] = locate(s);
    return segs[i].point(u);
  }

  Tensor<1, 2> CurveChain::tangent_at(const double s) const
  {
    const auto [i, u] = locate(s);
    return segs[i].tangent(u);
  }

  Tensor<1, 2> CurveChain::normal_at(const double s) const
  {
    const auto [i, u] = locate(s);
    return segs[i].normal(u);
  }

  SurfaceProjection<2> CurveChain::project(const Point<2> &x, const double max_distance) const
  {
    const std::size_t n = segs.size();

    // 1. Globally closest segment point. Ties: the first segment wins, except that a point in a
    //    segment's interior beats an (equally far) clamped end point.
    int                        best_i = -1;
    CurveSegment::ClosestPoint best;
    const bool                 band = std::isfinite(max_distance);
    for (std::size_t i = 0; i < n; ++i)
    {
      if (band && segs[i].distance_to_bounding_box(x) > max_distance)
        continue;
      const CurveSegment::ClosestPoint lp = segs[i].closest_point(x);
      if (best_i < 0)
      {
        best_i = static_cast<int>(i), best = lp;
        continue;
      }
      const double tol = 1e-12 * best.distance_squared + 1e-28 * scale * scale;
      const bool   lp_end = lp.at_start || lp.at_end, best_end = best.at_start || best.at_end;
      if (lp.distance_squared < best.distance_squared - tol
          || (lp.distance_squared <= best.distance_squared + tol && best_end && !lp_end))
        best_i = static_cast<int>(i), best = lp;
    }

    SurfaceProjection<2> result;
    if (best_i < 0 || std::sqrt(best.distance_squared) > max_distance)
      return result;

    const unsigned int  i = static_cast<unsigned int>(best_i);
    const CurveSegment &seg = segs[i];
    const Tensor<1, 2>  v = x - best.point;
    const double        dist = v.norm();
    result.valid = true;
    result.point = best.point;
    result.distance = dist;
    result.coordinates[0] = segment_s[i] + best.u;
    if (closed)
      result.coordinates[0] = positive_modulo(result.coordinates[0], total_length());

    // A clamped end point is a joint (or an open end). A point lying exactly on a segment end is
    // treated as on the joint too if the joint is a real corner (bisector normal there).
    const bool   on_point = dist <= 1e-14 * scale;
    const bool   at_start = best.at_start || (on_point && best.u <= seg.u_begin());
    const bool   at_end = !at_start && (best.at_end || (on_point && best.u >= seg.u_end()));
    const bool   has_neighbour = closed ? true : (at_start ? i > 0 : i + 1 < n);
    Tensor<1, 2> t1, t2; // incoming and outgoing tangents at the joint
    double       turn = 0.0;
    if ((at_start || at_end) && has_neighbour)
    {
      const CurveSegment &in = at_start ? segs[(i + n - 1) % n] : seg;
      const CurveSegment &out = at_start ? seg : segs[(i + 1) % n];
      t1 = in.tangent(in.u_end());
      t2 = out.tangent(out.u_begin());
      turn = cross(t1, t2);
    }
    const bool smooth_joint = std::abs(turn) <= 1e-12 && t1 * t2 > 0.0;
    const bool use_joint = (best.at_start || best.at_end)
                           || ((at_start || at_end) && !(has_neighbour && smooth_joint));

    if (!use_joint)
    {
      // 2a. Interior of a segment: x - x_proj is along the segment normal.
      result.normal = seg.normal(best.u);
      result.gap = v * result.normal;
      result.curvatures[0] = seg.curvature(best.u);
    }
    else
    {
      // 2b. A joint or an open end: the normal is +-(x - x_proj)/|x - x_proj|.
      Tensor<1, 2> n_ref; // normal used if x is the corner itself
      bool         outside;
      if (has_neighbour)
      {
        const Tensor<1, 2> n1 = rotate_left(t1), n2 = rotate_left(t2);
        if (turn > 1e-12)
          // Concave corner: the open region is the intersection of both half planes.
          outside = (v * n1 >= 0.0) && (v * n2 >= 0.0);
        else if (!smooth_joint)
          // Convex corner (or a spike turning back): the open region is the union.
          outside = (v * n1 > 0.0) || (v * n2 > 0.0);
        else
          outside = (v * (n1 + n2) >= 0.0); // tangent-continuous joint
        n_ref = n1 + n2;
        if (n_ref.norm() < 1e-12)
          n_ref = n1;
        n_ref /= n_ref.norm();
        result.at_edge = true;
      }
      else
      {
        n_ref = seg.normal(at_start ? seg.u_begin() : seg.u_end());
        outside = (v * n_ref >= 0.0);
        result.at_end = true;
      }
      if (on_point)
      {
        result.normal = n_ref;
        result.gap = 0.0;
      }
      else
      {
        result.normal = (outside ? 1.0 : -1.0) * v / dist;
        result.gap = outside ? dist : -dist;
      }
      result.curvatures[0] = 0.0;
    }
    result.tangents[0] = rotate_right(result.normal);
    result.end_margin = outline_margin(result.coordinates[0]);
    return result;
  }
} // namespace ausroll::geometry
