/**
 * @file die_surface.cc
 * Implementation of the rigid die surfaces (see die_surface.h for the conventions).
 */
#include <ausroll/contact/die_surface.h>
#include <ausroll/core/exceptions.h>
#include <ausroll/core/input_file.h>
#include <ausroll/geometry/involute_gear.h>

#include <algorithm>
#include <fstream>
#include <sstream>

namespace ausroll::contact
{
  namespace
  {
    using dealii::Point;
    using dealii::Tensor;

    constexpr double inf = std::numeric_limits<double>::infinity();

    /** Unit vector e(a) = (cos a, sin a). */
    Tensor<1, 2> unit(const double a)
    {
      Tensor<1, 2> e;
      e[0] = std::cos(a);
      e[1] = std::sin(a);
      return e;
    }

    /** Vector @p v rotated by +90 degrees: (-v_y, v_x). */
    Tensor<1, 2> rotate_left(const Tensor<1, 2> &v)
    {
      Tensor<1, 2> r;
      r[0] = -v[1];
      r[1] = v[0];
      return r;
    }

    /** Vector @p v rotated by -90 degrees: (v_y, -v_x). */
    Tensor<1, 2> rotate_right(const Tensor<1, 2> &v)
    {
      Tensor<1, 2> r;
      r[0] = v[1];
      r[1] = -v[0];
      return r;
    }

    /** z-component of the cross product a x b. */
    double cross(const Tensor<1, 2> &a, const Tensor<1, 2> &b)
    {
      return a[0] * b[1] - a[1] * b[0];
    }

    /** @p a wrapped into [0, @p period). */
    double positive_modulo(const double a, const double period)
    {
      double r = std::fmod(a, period);
      if (r < 0.0)
        r += period;
      return (r >= period) ? 0.0 : r;
    }

    /** Rotate @p p about the origin by @p angle (counter-clockwise). */
    Point<2> rotate(const Point<2> &p, const double angle)
    {
      const double c = std::cos(angle), s = std::sin(angle);
      return Point<2>(c * p[0] - s * p[1], s * p[0] + c * p[1]);
    }

    /** Polar angle of @p v. */
    double polar_angle(const Tensor<1, 2> &v)
    {
      return std::atan2(v[1], v[0]);
    }

    const std::string die_entry = "Die surface";
  } // namespace

  // ------------------------------------------------------------------ DieSegment

  DieSegment DieSegment::line(const Point<2> &start, const Point<2> &end)
  {
    const double length = start.distance(end);
    require(length > 0.0, die_entry, "a line segment needs two distinct points");
    DieSegment seg;
    seg.kind = Type::line;
    seg.origin = start;
    seg.direction = (end - start) / length;
    seg.u_lo = 0.0;
    seg.u_hi = length;
    seg.compute_bounding_box();
    return seg;
  }

  DieSegment DieSegment::line_through(const Point<2>     &reference,
                                      const Tensor<1, 2> &direction,
                                      const double        u_begin,
                                      const double        u_end)
  {
    require(direction.norm() > 0.0, die_entry, "a line needs a non-zero direction");
    require(u_begin < u_end && !std::isnan(u_begin) && !std::isnan(u_end),
            die_entry,
            "a line needs u_begin < u_end");
    DieSegment seg;
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

  DieSegment DieSegment::arc(const Point<2> &center,
                             const double    radius,
                             const double    start_angle,
                             const double    sweep)
  {
    require(radius > 0.0 && std::isfinite(radius), die_entry, "an arc needs a positive radius");
    require(sweep != 0.0 && std::abs(sweep) <= 2.0 * M_PI * (1.0 + 1e-14),
            die_entry,
            "an arc needs a sweep angle with 0 < |sweep| <= 2 pi");
    DieSegment seg;
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

  DieSegment DieSegment::involute(const Point<2> &base_center,
                                  const double    base_radius,
                                  const double    origin_angle,
                                  const int       unwind_sense,
                                  const double    roll_start,
                                  const double    roll_end)
  {
    require(base_radius > 0.0, die_entry, "an involute needs a positive base radius");
    require(unwind_sense == 1 || unwind_sense == -1,
            die_entry,
            "the unwind sense of an involute must be +1 or -1");
    require(roll_start >= 0.0 && roll_end >= 0.0 && roll_start != roll_end,
            die_entry,
            "an involute needs two different non-negative roll angles");
    DieSegment seg;
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

  DieSegment DieSegment::reversed() const
  {
    DieSegment r = *this;
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

  double DieSegment::roll_angle(const double u) const
  {
    const double u2 = roll0 * roll0 + roll_direction * 2.0 * u / radius;
    return std::sqrt(std::max(0.0, u2));
  }

  double DieSegment::local_coordinate(const double roll) const
  {
    return roll_direction * 0.5 * radius * (roll * roll - roll0 * roll0);
  }

  Point<2> DieSegment::point(double u) const
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

  Tensor<1, 2> DieSegment::tangent(double u) const
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

  Tensor<1, 2> DieSegment::normal(const double u) const
  {
    return rotate_left(tangent(u));
  }

  double DieSegment::curvature(const double u) const
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

  DieSegment::LocalProjection DieSegment::closest_point(const Point<2> &x) const
  {
    // Candidates: the unconstrained critical points inside the range and, where the critical
    // point lies outside (or to be safe, for the involute), the clamped end points. An interior
    // candidate beats an equally far clamped one, so that "at_start / at_end" means "clamped".
    LocalProjection best;
    bool            best_clamped = false;
    const auto      consider = [&](const double u, const bool clamped)
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

  void DieSegment::compute_bounding_box()
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

  double DieSegment::distance_to_bounding_box(const Point<2> &x) const
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

  // ------------------------------------------------------------------ DieSurface

  DieSurface::DieSurface(std::vector<DieSegment> segments, const bool closed)
      : segs(std::move(segments))
      , closed(closed)
      , scale(0.0)
      , outline_begin(0.0)
      , outline_end(0.0)
  {
    require(!segs.empty(), die_entry, "a die surface needs at least one segment");
    const std::size_t n = segs.size();
    for (std::size_t i = 0; i < n; ++i)
    {
      require(std::isfinite(segs[i].u_begin()) || (i == 0 && !closed),
              die_entry,
              "only the first segment of an open chain may start at infinity");
      require(std::isfinite(segs[i].u_end()) || (i + 1 == n && !closed),
              die_entry,
              "only the last segment of an open chain may end at infinity");
    }

    // Size of the die for tolerances: bounding box of all finite points.
    std::vector<Point<2>> corners;
    for (const DieSegment &seg : segs)
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
    for (const DieSegment &seg : segs)
      if (seg.is_bounded())
        scale = std::max(scale, seg.length());

    const double tol = 1e-8 * scale;
    for (std::size_t i = 0; i + 1 < n + (closed ? 1 : 0); ++i)
    {
      const DieSegment &a = segs[i], &b = segs[(i + 1) % n];
      if (a.end_point().distance(b.start_point()) > tol)
      {
        std::ostringstream msg;
        msg << "segment " << i << " ends at (" << a.end_point() << ") but segment " << (i + 1) % n
            << " starts at (" << b.start_point() << ")";
        throw InputError(die_entry + ": " + msg.str());
      }
    }

    segment_s.resize(n, 0.0);
    for (std::size_t i = 0; i + 1 < n; ++i)
      segment_s[i + 1] = segment_s[i] + segs[i].u_end();
    outline_begin = s_begin();
    outline_end = s_end();
  }

  void DieSurface::set_outline(const Point<2> &first, const Point<2> &last)
  {
    outline_begin = segment_s.front() + segs.front().closest_point(first).u;
    outline_end = segment_s.back() + segs.back().closest_point(last).u;
  }

  double
  DieSurface::outline_margin(const double s, const bool count_start, const bool count_end) const
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

  DieSurface
  DieSurface::flat(const Point<2> &point, const Tensor<1, 2> &direction, const double half_length)
  {
    require(half_length > 0.0, die_entry, "a flat die needs a positive half length");
    require(direction.norm() > 0.0, die_entry, "a flat die needs a non-zero direction");
    if (std::isinf(half_length))
      return DieSurface({DieSegment::line_through(point, direction, -inf, inf)}, false);
    const Tensor<1, 2> d = direction / direction.norm();
    return DieSurface({DieSegment::line(point - half_length * d, point + half_length * d)}, false);
  }

  DieSurface
  DieSurface::circle(const Point<2> &center, const double radius, const bool material_inside)
  {
    return DieSurface(
        {DieSegment::arc(center, radius, 0.0, material_inside ? -2.0 * M_PI : 2.0 * M_PI)}, true);
  }

  DieSurface DieSurface::polyline(const std::vector<Point<2>> &points,
                                  const bool                   closed,
                                  const bool                   extend_ends)
  {
    require(
        !(closed && extend_ends), die_entry, "a closed polyline cannot be extended to infinity");
    std::vector<Point<2>> p;
    for (const Point<2> &q : points)
      if (p.empty() || q.distance(p.back()) > 0.0)
        p.push_back(q);
    if (closed && p.size() > 1 && p.back().distance(p.front()) == 0.0)
      p.pop_back();
    require(p.size() >= (closed ? 3u : 2u),
            die_entry,
            closed ? "a closed polyline needs at least 3 distinct points"
                   : "a polyline needs at least 2 distinct points");

    std::vector<DieSegment> segments;
    const std::size_t       n_sides = closed ? p.size() : p.size() - 1;
    for (std::size_t i = 0; i < n_sides; ++i)
    {
      const Point<2> &a = p[i], &b = p[(i + 1) % p.size()];
      const double    l = a.distance(b);
      const bool      to_first = extend_ends && i == 0, to_last = extend_ends && i + 1 == n_sides;
      if (to_first || to_last)
        segments.push_back(
            DieSegment::line_through(a, b - a, to_first ? -inf : 0.0, to_last ? inf : l));
      else
        segments.push_back(DieSegment::line(a, b));
    }
    DieSurface die(std::move(segments), closed);
    if (extend_ends)
      die.set_outline(p.front(), p.back());
    return die;
  }

  std::vector<Point<2>> DieSurface::read_points_file(const std::string &filename)
  {
    const std::string where = "Die surface points file '" + filename + "'";
    std::ifstream     in
        = open_input_file(filename, "Die surface points file", file_size_limit::points_file);
    std::vector<Point<2>> points;
    std::string           line;
    unsigned int          line_number = 0;
    while (std::getline(in, line))
    {
      ++line_number;
      const std::size_t comment = line.find('#');
      if (comment != std::string::npos)
        line.erase(comment);
      std::istringstream fields(line);
      double             x, y;
      if (!(fields >> x))
      {
        // A blank (or comment-only) line is fine; anything else is an error.
        fields.clear();
        std::string rest;
        if (fields >> rest)
          throw InputError(where + ": line " + std::to_string(line_number)
                           + " is not of the form 'x y'");
        continue;
      }
      std::string rest;
      if (!(fields >> y) || (fields >> rest))
        throw InputError(where + ": line " + std::to_string(line_number)
                         + " is not of the form 'x y'");
      points.emplace_back(x, y);
    }
    if (in.bad())
      throw InputError(where + ": read error");
    if (points.size() < 2)
      throw InputError(where + ": needs at least 2 points, found " + std::to_string(points.size()));
    return points;
  }

  DieSurface DieSurface::polyline_from_file(const std::string &filename, const bool extend_ends)
  {
    const std::vector<Point<2>> points = read_points_file(filename);
    try
    {
      return polyline(points, false, extend_ends);
    }
    catch (const InputError &e)
    {
      throw InputError("Die surface points file '" + filename + "': " + e.what());
    }
  }

  DieSurface DieSurface::arc_line_composite(const std::vector<Point<2>> &points,
                                            const std::vector<double>   &fillet_radii,
                                            const bool                   closed,
                                            const bool                   extend_ends)
  {
    require(!(closed && extend_ends),
            die_entry,
            "a closed line-arc composite cannot be extended to infinity");
    const std::size_t n = points.size();
    require(n >= (closed ? 3u : 2u), die_entry, "a line-arc composite needs more points");
    const std::size_t n_corners = closed ? n : n - 2;
    require(fillet_radii.size() == n_corners || fillet_radii.size() == 1,
            die_entry,
            "a line-arc composite needs one fillet radius per corner (or a single one)");
    for (std::size_t i = 0; i + 1 < n + (closed ? 1 : 0); ++i)
      require(points[i].distance(points[(i + 1) % n]) > 0.0,
              die_entry,
              "consecutive corner points of a line-arc composite must differ");

    // Corner i (at points[i]): fillet radius, turning angle, tangent length.
    struct Corner
    {
      double       radius = 0.0, turn = 0.0, tangent_length = 0.0;
      Tensor<1, 2> d_in, d_out;
    };
    std::vector<Corner> corners(n);
    for (std::size_t i = 0; i < n; ++i)
    {
      const bool interior = closed || (i > 0 && i + 1 < n);
      if (!interior)
        continue;
      Corner         &c = corners[i];
      const Point<2> &prev = points[(i + n - 1) % n], &next = points[(i + 1) % n];
      c.d_in = (points[i] - prev) / points[i].distance(prev);
      c.d_out = (next - points[i]) / next.distance(points[i]);
      c.turn = std::atan2(cross(c.d_in, c.d_out), c.d_in * c.d_out);
      c.radius = fillet_radii.size() == 1 ? fillet_radii[0] : fillet_radii[closed ? i : i - 1];
      require(c.radius >= 0.0, die_entry, "fillet radii must not be negative");
      require(std::abs(c.turn) < M_PI * (1.0 - 1e-12) || c.radius == 0.0,
              die_entry,
              "a fillet cannot round a corner that turns back by 180 degrees");
      if (c.radius > 0.0 && std::abs(c.turn) > 1e-12)
        c.tangent_length = c.radius * std::tan(0.5 * std::abs(c.turn));
    }
    for (std::size_t i = 0; i + 1 < n + (closed ? 1 : 0); ++i)
    {
      const std::size_t j = (i + 1) % n;
      require(corners[i].tangent_length + corners[j].tangent_length
                  <= points[i].distance(points[j]) * (1.0 + 1e-12),
              die_entry,
              "the fillets at points " + std::to_string(i) + " and " + std::to_string(j)
                  + " do not fit on the side between them");
    }

    // Walk the corners: a straight piece up to the first tangency point, then the fillet arc.
    std::vector<DieSegment> segments;
    const auto              add_line = [&](const Point<2> &a, const Point<2> &b)
    {
      if (a.distance(b) > 1e-12 * a.distance(points[0]) + 1e-300)
        segments.push_back(DieSegment::line(a, b));
    };
    const auto add_fillet = [&](const std::size_t i)
    {
      const Corner &c = corners[i];
      if (c.tangent_length == 0.0)
        return;
      const Point<2> t1 = points[i] - c.tangent_length * c.d_in;
      const double   side = c.turn > 0.0 ? 1.0 : -1.0;
      const Point<2> center = t1 + side * c.radius * rotate_left(c.d_in);
      segments.push_back(DieSegment::arc(center, c.radius, polar_angle(t1 - center), c.turn));
    };
    const auto after = [&](const std::size_t i)
    { return points[i] + corners[i].tangent_length * corners[i].d_out; };
    const auto before = [&](const std::size_t i)
    { return points[i] - corners[i].tangent_length * corners[i].d_in; };

    if (closed)
    {
      for (std::size_t k = 1; k <= n; ++k)
      {
        const std::size_t i = k % n;
        add_line(after(k - 1), before(i));
        add_fillet(i);
      }
    }
    else
    {
      Point<2> start = points[0];
      for (std::size_t i = 1; i + 1 < n; ++i)
      {
        add_line(start, before(i));
        add_fillet(i);
        start = after(i);
      }
      add_line(start, points[n - 1]);
    }

    if (extend_ends)
    {
      // First and last piece become rays to infinity (inserted if the fillet consumed them).
      const Tensor<1, 2> d_first = (points[1] - points[0]) / points[1].distance(points[0]);
      const Tensor<1, 2> d_last
          = (points[n - 1] - points[n - 2]) / points[n - 1].distance(points[n - 2]);
      if (segments.front().type() == DieSegment::Type::line
          && segments.front().start_point().distance(points[0]) == 0.0)
        segments.front()
            = DieSegment::line_through(points[0], d_first, -inf, segments.front().u_end());
      else
        segments.insert(segments.begin(), DieSegment::line_through(points[0], d_first, -inf, 0.0));
      if (segments.size() > 1 && segments.back().type() == DieSegment::Type::line
          && segments.back().end_point().distance(points[n - 1]) == 0.0)
        segments.back() = DieSegment::line_through(segments.back().start_point(), d_last, 0.0, inf);
      else if (segments.size() == 1)
        segments.back() = DieSegment::line_through(points[0], d_first, -inf, inf);
      else
        segments.push_back(DieSegment::line_through(points[n - 1], d_last, 0.0, inf));
    }
    DieSurface die(std::move(segments), closed);
    if (extend_ends)
      die.set_outline(points[0], points[n - 1]);
    return die;
  }

  DieSurface DieSurface::involute_flank(const Point<2> &base_center,
                                        const double    base_radius,
                                        const double    origin_angle,
                                        const int       unwind_sense,
                                        const double    roll_start,
                                        const double    roll_end)
  {
    return DieSurface(
        {DieSegment::involute(
            base_center, base_radius, origin_angle, unwind_sense, roll_start, roll_end)},
        false);
  }

  DieSurface DieSurface::involute_gear(const geometry::InvoluteGear &gear,
                                       const double                  tooth_axis_angle,
                                       const unsigned int            n_teeth,
                                       const double                  tip_round)
  {
    using geometry::FlankSide;
    const geometry::ToothGeometry &tooth = gear.tooth_geometry();
    const unsigned int             z = gear.n_teeth();
    if (n_teeth > z)
      throw EntryError("Teeth in sector",
                       std::to_string(n_teeth) + " is more than the gear's " + std::to_string(z)
                           + " teeth");
    const bool     full = (n_teeth == 0 || n_teeth == z);
    const unsigned n = full ? z : n_teeth;
    const double   rb = gear.base_radius();
    const double   rr = gear.root_radius();
    const double   rt = gear.tip_radius();
    const double   rho = gear.root_fillet_radius();
    const double   r_fl = tooth.flank_start_radius;
    const double   psi = tooth.root_land_angle;
    const double   pitch = gear.angular_pitch();
    const double   u_low = gear.roll_angle_at(std::max(r_fl, rb));
    const Point<2> o;
    const double   land_tol = 1e-12;

    // Tip round (tooth axis along +x, positive flank): centre c at radius r_c = r_a - rho_t and
    // at the normal distance rho_t inside the involute. The normal of an involute through a point
    // is the tangent from it to the base circle, and the distance between two rotated copies of
    // the involute along it is r_b times the rotation: phi_c = theta_h(r_c) - rho_t / r_b. The
    // tangent point Q on the flank lies on that base tangent at r_b u_Q = rho_t +
    // sqrt(r_c^2 - r_b^2) from the tangency point; the tangent point on the outside circle lies
    // on the ray through c.
    if (tip_round < 0.0)
      throw EntryError("Tip radius", "the tip round radius must not be negative");
    double   u_tip = gear.roll_angle_at(rt);
    double   tip_angle = tooth.tip_half_angle;
    Point<2> round_center;
    double   round_from = 0.0;
    if (tip_round > 0.0)
    {
      const double r_c = rt - tip_round;
      if (!(r_c > rb))
        throw EntryError("Tip radius", "the tip round must end above the base circle");
      tip_angle = gear.half_thickness_angle(r_c) - tip_round / rb;
      if (!(tip_angle > 0.0))
        throw EntryError("Tip radius", "the tip round is too large: no tip land remains");
      u_tip = (tip_round + std::sqrt(r_c * r_c - rb * rb)) / rb;
      require(u_tip > u_low, die_entry, "the tip round reaches below the involute flank");
      round_center = Point<2>(r_c * unit(tip_angle));
      const Point<2> q = gear.flank_point(rb * std::sqrt(1.0 + u_tip * u_tip), FlankSide::positive);
      round_from = polar_angle(q - round_center);
    }

    std::vector<DieSegment> segments;
    // One tooth with axis at polar angle a, travelled clockwise (root land side at a + psi first).
    const auto add_tooth = [&](const double a)
    {
      const auto fillet = [&](const Point<2> &center, const Point<2> &from, const Point<2> &to)
      {
        // The fillet is concave (centre in the tooth space): travelled counter-clockwise.
        const double phi_from = polar_angle(from - center);
        const double sweep = positive_modulo(polar_angle(to - center) - phi_from, 2.0 * M_PI);
        segments.push_back(DieSegment::arc(center, rho, phi_from, sweep));
      };
      const Point<2> p_pos = rotate(gear.flank_point(r_fl, FlankSide::positive), a);
      const Point<2> p_neg = rotate(gear.flank_point(r_fl, FlankSide::negative), a);
      if (rho > 0.0)
        fillet(rotate(tooth.fillet_center, a), o + rr * unit(a + psi), p_pos);
      if (tooth.has_radial_flank)
        segments.push_back(
            DieSegment::line(p_pos, rotate(gear.flank_point(rb, FlankSide::positive), a)));
      segments.push_back(DieSegment::involute(o, rb, a + tooth.base_half_angle, -1, u_low, u_tip));
      // convex tip rounds travelled clockwise: from the flank to the outside circle
      const double round_sweep = -positive_modulo(round_from - tip_angle, 2.0 * M_PI);
      if (tip_round > 0.0)
        segments.push_back(
            DieSegment::arc(rotate(round_center, a), tip_round, a + round_from, round_sweep));
      segments.push_back(DieSegment::arc(o, rt, a + tip_angle, -2.0 * tip_angle));
      if (tip_round > 0.0)
        segments.push_back(DieSegment::arc(rotate(Point<2>(round_center[0], -round_center[1]), a),
                                           tip_round,
                                           a - tip_angle,
                                           round_sweep));
      segments.push_back(DieSegment::involute(o, rb, a - tooth.base_half_angle, +1, u_tip, u_low));
      if (tooth.has_radial_flank)
        segments.push_back(
            DieSegment::line(rotate(gear.flank_point(rb, FlankSide::negative), a), p_neg));
      if (rho > 0.0)
      {
        const Point<2> c(tooth.fillet_center[0], -tooth.fillet_center[1]);
        fillet(rotate(c, a), p_neg, o + rr * unit(a - psi));
      }
    };
    const auto add_root_land = [&](const double from, const double to)
    {
      if (from - to > land_tol)
        segments.push_back(DieSegment::arc(o, rr, from, to - from));
    };

    if (full)
      for (unsigned int k = 0; k < n; ++k)
      {
        const double a = tooth_axis_angle - k * pitch;
        add_tooth(a);
        add_root_land(a - psi, a - pitch + psi);
      }
    else
    {
      const double a0 = tooth_axis_angle + 0.5 * (n - 1.0) * pitch;
      add_root_land(a0 + 0.5 * pitch, a0 + psi);
      for (unsigned int k = 0; k < n; ++k)
      {
        const double a = a0 - k * pitch;
        add_tooth(a);
        add_root_land(a - psi, k + 1 < n ? a - pitch + psi : a - 0.5 * pitch);
      }
    }
    return DieSurface(std::move(segments), full);
  }

  DieSurface DieSurface::reversed() const
  {
    std::vector<DieSegment> r;
    r.reserve(segs.size());
    for (auto it = segs.rbegin(); it != segs.rend(); ++it)
      r.push_back(it->reversed());
    DieSurface result(std::move(r), closed);
    if (!closed && (outline_begin != s_begin() || outline_end != s_end()))
      result.set_outline(point_at(outline_end), point_at(outline_begin));
    return result;
  }

  double DieSurface::total_length() const
  {
    return s_end() - s_begin();
  }

  std::pair<unsigned int, double> DieSurface::locate(double s) const
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

  Point<2> DieSurface::point_at(const double s) const
  {
    const auto [i, u] = locate(s);
    return segs[i].point(u);
  }

  Tensor<1, 2> DieSurface::tangent_at(const double s) const
  {
    const auto [i, u] = locate(s);
    return segs[i].tangent(u);
  }

  Tensor<1, 2> DieSurface::normal_at(const double s) const
  {
    const auto [i, u] = locate(s);
    return segs[i].normal(u);
  }

  Projection DieSurface::project(const Point<2> &x, const double max_distance) const
  {
    const std::size_t n = segs.size();

    // 1. Globally closest segment point. Ties: the first segment wins, except that a point in a
    //    segment's interior beats an (equally far) clamped end point.
    int                         best_i = -1;
    DieSegment::LocalProjection best;
    const bool                  band = std::isfinite(max_distance);
    for (std::size_t i = 0; i < n; ++i)
    {
      if (band && segs[i].distance_to_bounding_box(x) > max_distance)
        continue;
      const DieSegment::LocalProjection lp = segs[i].closest_point(x);
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

    Projection result;
    if (best_i < 0 || std::sqrt(best.distance_squared) > max_distance)
      return result;

    const unsigned int i = static_cast<unsigned int>(best_i);
    const DieSegment  &seg = segs[i];
    const Tensor<1, 2> v = x - best.point;
    const double       dist = v.norm();
    result.valid = true;
    result.point = best.point;
    result.segment = i;
    result.distance = dist;
    result.s = segment_s[i] + best.u;
    if (closed)
      result.s = positive_modulo(result.s, total_length());

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
      const DieSegment &in = at_start ? segs[(i + n - 1) % n] : seg;
      const DieSegment &out = at_start ? seg : segs[(i + 1) % n];
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
      result.curvature = seg.curvature(best.u);
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
        result.at_corner = true;
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
      result.curvature = 0.0;
    }
    result.tangent = rotate_right(result.normal);
    result.end_margin = outline_margin(result.s);
    return result;
  }
  // ------------------------------------------------------------------ ChainSurface

  ChainSurface::ChainSurface(std::string name, DieSurface chain)
      : shape_name(std::move(name))
      , die(std::move(chain))
  {
  }

  SurfaceProjection<2> ChainSurface::project(const Point<2> &x, const double max_distance) const
  {
    const Projection     p = die.project(x, max_distance);
    SurfaceProjection<2> result;
    if (!p.valid)
      return result;
    result.valid = true;
    result.point = p.point;
    result.gap = p.gap;
    result.distance = p.distance;
    result.normal = p.normal;
    result.tangents[0] = p.tangent;
    result.curvatures[0] = p.curvature;
    result.coordinates[0] = p.s;
    result.at_edge = p.at_corner;
    result.at_end = p.at_end;
    result.end_margin = p.end_margin;
    return result;
  }

  Point<2> ChainSurface::point_at(const std::array<double, 1> &coordinates) const
  {
    return die.point_at(coordinates[0]);
  }

  std::array<double, 1> ChainSurface::coordinate_periods() const
  {
    return {{die.is_closed() ? die.total_length() : 0.0}};
  }
} // namespace ausroll::contact
