/**
 * @file curve_segment.cc
 * The segments of 2D curves (see curve_segment.h and, for the conventions, curve_chain.h).
 */
#include <ausroll/core/exceptions.h>
#include <ausroll/geometry/curve_segment.h>
#include <ausroll/geometry/plane_vectors.h>

#include <algorithm>

namespace ausroll::geometry
{
  using dealii::Point;
  using dealii::Tensor;
  using namespace plane;

  // ------------------------------------------------------------------ CurveSegment

  CurveSegment CurveSegment::line(const Point<2> &start, const Point<2> &end)
  {
    const double length = start.distance(end);
    require(length > 0.0, plane::curve_entry, "a line segment needs two distinct points");
    CurveSegment seg;
    seg.kind = Type::line;
    seg.origin = start;
    seg.direction = (end - start) / length;
    seg.u_lo = 0.0;
    seg.u_hi = length;
    seg.compute_bounding_box();
    return seg;
  }

  CurveSegment CurveSegment::line_through(const Point<2>     &reference,
                                          const Tensor<1, 2> &direction,
                                          const double        u_begin,
                                          const double        u_end)
  {
    require(direction.norm() > 0.0, plane::curve_entry, "a line needs a non-zero direction");
    require(u_begin < u_end && !std::isnan(u_begin) && !std::isnan(u_end),
            plane::curve_entry,
            "a line needs u_begin < u_end");
    CurveSegment seg;
    seg.kind = Type::line;
    seg.direction = direction / direction.norm();
    if (std::isfinite(u_begin))
    {
      // Normalize so that u = 0 at the start point.
      seg.origin = reference + u_begin * seg.direction;
      seg.u_lo = 0.0;
      seg.u_hi = u_end - u_begin;
    }
    else
    {
      seg.origin = reference;
      seg.u_lo = u_begin;
      seg.u_hi = u_end;
    }
    seg.compute_bounding_box();
    return seg;
  }

  CurveSegment CurveSegment::arc(const Point<2> &center,
                                 const double    radius,
                                 const double    start_angle,
                                 const double    sweep)
  {
    require(radius > 0.0 && std::isfinite(radius),
            plane::curve_entry,
            "an arc needs a positive radius");
    require(sweep != 0.0 && std::abs(sweep) <= 2.0 * M_PI * (1.0 + 1e-14),
            plane::curve_entry,
            "an arc needs a sweep angle with 0 < |sweep| <= 2 pi");
    CurveSegment seg;
    seg.kind = Type::arc;
    seg.origin = center;
    seg.radius = radius;
    seg.angle0 = start_angle;
    seg.sweep = std::max(-2.0 * M_PI, std::min(2.0 * M_PI, sweep));
    seg.u_lo = 0.0;
    seg.u_hi = radius * std::abs(seg.sweep);
    seg.compute_bounding_box();
    return seg;
  }

  CurveSegment CurveSegment::involute(const Point<2> &base_center,
                                      const double    base_radius,
                                      const double    origin_angle,
                                      const int       unwind_sense,
                                      const double    roll_start,
                                      const double    roll_end)
  {
    require(base_radius > 0.0, plane::curve_entry, "an involute needs a positive base radius");
    require(unwind_sense == 1 || unwind_sense == -1,
            plane::curve_entry,
            "the unwind sense of an involute must be +1 or -1");
    require(roll_start >= 0.0 && roll_end >= 0.0 && roll_start != roll_end,
            plane::curve_entry,
            "an involute needs two different non-negative roll angles");
    CurveSegment seg;
    seg.kind = Type::involute;
    seg.origin = base_center;
    seg.radius = base_radius;
    seg.angle0 = origin_angle;
    seg.sweep = unwind_sense;
    seg.roll0 = roll_start;
    seg.roll_direction = (roll_end > roll_start) ? 1.0 : -1.0;
    seg.u_lo = 0.0;
    seg.u_hi = 0.5 * base_radius * std::abs(roll_end * roll_end - roll_start * roll_start);
    seg.compute_bounding_box();
    return seg;
  }

  CurveSegment CurveSegment::reversed() const
  {
    CurveSegment r = *this;
    switch (kind)
    {
      case Type::line:
        r.direction = -direction;
        if (std::isfinite(u_hi))
        {
          r.origin = point(u_hi);
          r.u_lo = 0.0;
          r.u_hi = u_hi - u_lo;
        }
        else
        {
          r.u_lo = -u_hi;
          r.u_hi = -u_lo;
        }
        break;
      case Type::arc:
        r.angle0 = angle0 + sweep;
        r.sweep = -sweep;
        break;
      case Type::involute:
        r.roll0 = roll_angle(u_hi);
        r.roll_direction = -roll_direction;
        break;
    }
    return r;
  }

  double CurveSegment::roll_angle(const double u) const
  {
    const double u2 = roll0 * roll0 + roll_direction * 2.0 * u / radius;
    return std::sqrt(std::max(0.0, u2));
  }

  double CurveSegment::local_coordinate(const double roll) const
  {
    return roll_direction * 0.5 * radius * (roll * roll - roll0 * roll0);
  }

  Point<2> CurveSegment::point(double u) const
  {
    u = std::max(u_lo, std::min(u_hi, u));
    switch (kind)
    {
      case Type::line:
        return origin + u * direction;
      case Type::arc:
        return origin + radius * unit(angle0 + (sweep > 0.0 ? 1.0 : -1.0) * u / radius);
      case Type::involute:
      {
        const double roll = roll_angle(u);
        const double theta_t = angle0 + sweep * roll;
        return origin + radius * (unit(theta_t) - sweep * roll * rotate_left(unit(theta_t)));
      }
    }
    return origin;
  }

  Tensor<1, 2> CurveSegment::tangent(double u) const
  {
    u = std::max(u_lo, std::min(u_hi, u));
    switch (kind)
    {
      case Type::line:
        return direction;
      case Type::arc:
      {
        const double sign = (sweep > 0.0) ? 1.0 : -1.0;
        return sign * rotate_left(unit(angle0 + sign * u / radius));
      }
      case Type::involute:
        // d x / d roll = r_b roll e(theta_T): the tangent is radial to the tangent point.
        return roll_direction * unit(angle0 + sweep * roll_angle(u));
    }
    return direction;
  }

  Tensor<1, 2> CurveSegment::normal(const double u) const
  {
    return rotate_left(tangent(u));
  }

  double CurveSegment::curvature(const double u) const
  {
    switch (kind)
    {
      case Type::line:
        return 0.0;
      case Type::arc:
        // Clockwise travel: material inside the circle, convex.
        return (sweep > 0.0 ? -1.0 : 1.0) / radius;
      case Type::involute:
      {
        // Centre of curvature (the tangent point on the base circle) relative to the curve
        // point: sweep * roll * r_b * e_perp(theta_T); the normal is roll_direction * e_perp.
        const double roll = roll_angle(std::max(u_lo, std::min(u_hi, u)));
        const double sign = -sweep * roll_direction;
        return roll > 0.0 ? sign / (radius * roll) : sign * inf;
      }
    }
    return 0.0;
  }

  CurveSegment::ClosestPoint CurveSegment::closest_point(const Point<2> &x) const
  {
    // Candidates: the unconstrained critical points inside the range and, where the critical
    // point lies outside (or to be safe, for the involute), the clamped end points. An interior
    // candidate beats an equally far clamped one, so that "at_start / at_end" means "clamped".
    ClosestPoint best;
    bool         best_clamped = false;
    const auto   consider = [&](const double u, const bool clamped)
    {
      const double   uc = std::max(u_lo, std::min(u_hi, u));
      const Point<2> p = point(uc);
      const double   d2 = (x - p).norm_square();
      if (d2 < best.distance_squared
          || (d2 <= best.distance_squared * (1.0 + 1e-14) && best_clamped && !clamped))
      {
        best.point = p;
        best.u = uc;
        best.distance_squared = d2;
        best_clamped = clamped;
      }
    };

    switch (kind)
    {
      case Type::line:
      {
        const double u = (x - origin) * direction;
        consider(u, u < u_lo || u > u_hi);
        break;
      }
      case Type::arc:
      {
        const Tensor<1, 2> v = x - origin;
        if (v.norm() <= 1e-300)
          consider(0.5 * (u_lo + u_hi), false); // every arc point is equally far
        else
        {
          const double sign = (sweep > 0.0) ? 1.0 : -1.0;
          const double delta = positive_modulo(sign * (polar_angle(v) - angle0), 2.0 * M_PI);
          if (delta <= std::abs(sweep))
            consider(radius * delta, false);
          else
          {
            consider(u_lo, true);
            consider(u_hi, true);
          }
        }
        break;
      }
      case Type::involute:
      {
        // Every normal line of an involute is tangent to its base circle. Hence the interior
        // critical points of the distance are the (at most two) tangent points of the lines
        // through x tangent to the base circle: x - c = r_b e(theta_T) + mu e_perp(theta_T)
        // with mu = +-sqrt(|x - c|^2 - r_b^2), i.e. theta_T = arg(x - c) - atan2(mu, r_b).
        // Candidates: those roll angles inside the range, plus both end points.
        consider(u_lo, true);
        consider(u_hi, true);
        const Tensor<1, 2> v = x - origin;
        const double       rho2 = v.norm_square();
        const double       roll_min = std::min(roll_angle(u_lo), roll_angle(u_hi));
        const double       roll_max = std::max(roll_angle(u_lo), roll_angle(u_hi));
        if (rho2 >= radius * radius)
        {
          const double mu = std::sqrt(rho2 - radius * radius);
          for (const double m : {mu, -mu})
          {
            const double theta_t = polar_angle(v) - std::atan2(m, radius);
            for (double roll = positive_modulo(sweep * (theta_t - angle0), 2.0 * M_PI);
                 roll <= roll_max;
                 roll += 2.0 * M_PI)
              if (roll >= roll_min)
                consider(local_coordinate(roll), false);
          }
        }
        break;
      }
    }
    best.at_start = best_clamped && best.u <= u_lo;
    best.at_end = best_clamped && best.u >= u_hi;
    return best;
  }

  void CurveSegment::compute_bounding_box()
  {
    if (!is_bounded())
      return;
    box_min = box_max = start_point();
    const auto include = [&](const Point<2> &p)
    {
      for (unsigned int d = 0; d < 2; ++d)
      {
        box_min[d] = std::min(box_min[d], p[d]);
        box_max[d] = std::max(box_max[d], p[d]);
      }
    };
    include(end_point());
    if (kind == Type::arc)
    {
      // Axis extremes where the polar angle is a multiple of pi/2.
      const double sign = (sweep > 0.0) ? 1.0 : -1.0;
      for (double t = positive_modulo(-sign * angle0, 0.5 * M_PI); t <= std::abs(sweep);
           t += 0.5 * M_PI)
        include(point(radius * t));
    }
    else if (kind == Type::involute)
    {
      // Axis extremes where the tangent e(theta_T) is axis aligned: theta_T = k pi / 2.
      const double roll_min = std::min(roll_angle(u_lo), roll_angle(u_hi));
      const double roll_max = std::max(roll_angle(u_lo), roll_angle(u_hi));
      for (double roll = positive_modulo(-sweep * angle0, 0.5 * M_PI); roll <= roll_max;
           roll += 0.5 * M_PI)
        if (roll >= roll_min)
          include(point(local_coordinate(roll)));
    }
  }

  double CurveSegment::distance_to_bounding_box(const Point<2> &x) const
  {
    if (!is_bounded())
      return 0.0;
    double d2 = 0.0;
    for (unsigned int d = 0; d < 2; ++d)
    {
      const double e = std::max({box_min[d] - x[d], 0.0, x[d] - box_max[d]});
      d2 += e * e;
    }
    return std::sqrt(d2);
  }
} // namespace ausroll::geometry
