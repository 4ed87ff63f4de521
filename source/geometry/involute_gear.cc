/**
 * @file involute_gear.cc
 * Implementation of the involute spur gear geometry (see involute_gear.h for the conventions).
 */
#include <ausroll/core/exceptions.h>
#include <ausroll/geometry/involute_gear.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace ausroll::geometry
{
  namespace
  {
    /** EntryError naming the gear entry (Number of teeth, Pressure angle, ...) unless @p ok. */
    void require_entry(const bool ok, const char *entry, const std::string &what)
    {
      if (!ok)
        throw EntryError(entry, what);
    }
  } // namespace

  namespace
  {
    using dealii::Point;
    using dealii::Tensor;

    /** Unit vector at polar angle @p phi. */
    Tensor<1, 2> unit(const double phi)
    {
      Tensor<1, 2> e;
      e[0] = std::cos(phi);
      e[1] = std::sin(phi);
      return e;
    }

    /** Point at polar coordinates (@p r, @p phi) about the origin. */
    Point<2> polar_point(const double r, const double phi)
    {
      return Point<2>(r * std::cos(phi), r * std::sin(phi));
    }

    /** Mirror image of @p p about the x axis. */
    Point<2> mirror(const Point<2> &p)
    {
      return Point<2>(p[0], -p[1]);
    }

    /** Rotate @p p about the origin by @p angle (counter-clockwise). */
    Point<2> rotate(const Point<2> &p, const double angle)
    {
      const double c = std::cos(angle), s = std::sin(angle);
      return Point<2>(c * p[0] - s * p[1], s * p[0] + c * p[1]);
    }

    /** Number of equal segments so that none is longer than @p h (at least one). */
    unsigned int n_segments(const double length, const double h)
    {
      return std::max(1u, static_cast<unsigned int>(std::ceil(length / h - 1e-9)));
    }

    /** Append the points of an arc (excluding its start point) with the given part tag. */
    void append_arc(ToothOutline     &outline,
                    const Point<2>   &center,
                    const double      radius,
                    const double      phi_start,
                    const double      phi_end,
                    const OutlinePart part,
                    const double      h)
    {
      const unsigned int n = n_segments(radius * std::abs(phi_end - phi_start), h);
      for (unsigned int j = 1; j <= n; ++j)
      {
        const double phi = phi_start + (phi_end - phi_start) * j / n;
        outline.points.push_back(center + radius * unit(phi));
        outline.parts.push_back(part);
      }
    }

    /** Append a straight segment sampled into equal pieces (excluding its start point). */
    void append_line(ToothOutline     &outline,
                     const Point<2>   &start,
                     const Point<2>   &end,
                     const OutlinePart part,
                     const double      h)
    {
      const unsigned int n = n_segments(start.distance(end), h);
      for (unsigned int j = 1; j <= n; ++j)
      {
        outline.points.push_back(start + (end - start) * (static_cast<double>(j) / n));
        outline.parts.push_back(part);
      }
    }
  } // namespace

  InvoluteGear::InvoluteGear(const unsigned int      n_teeth,
                             const double            module,
                             const double            pressure_angle,
                             const ToothProportions &proportions)
      : z(n_teeth)
      , m(module)
      , alpha(pressure_angle)
      , add(proportions.addendum.value_or(module))
      , ded(proportions.dedendum.value_or(1.25 * module))
      , s_p(proportions.pitch_tooth_thickness.value_or(0.5 * M_PI * module))
      , rho_f(proportions.root_fillet_radius)
  {
    require_entry(z >= 3, "Number of teeth", "the number of teeth must be at least 3");
    require_entry(m > 0.0 && std::isfinite(m), "Module", "the module must be positive");
    require_entry(alpha > 0.0 && alpha < 0.5 * M_PI,
                  "Pressure angle",
                  "the pressure angle must lie strictly between 0 and 90 degrees");
    require_entry(add > 0.0, "Addendum", "the addendum must be positive");
    require_entry(ded > 0.0, "Dedendum", "the dedendum must be positive");
    require_entry(root_radius() > 0.0, "Dedendum", "the dedendum is larger than the pitch radius");
    require_entry(s_p > 0.0 && s_p < circular_pitch(),
                  "Tooth thickness",
                  "the pitch tooth thickness must lie between 0 and the circular pitch");
    require_entry(
        rho_f >= 0.0, "Root fillet radius", "the root fillet radius must not be negative");
    compute_tooth_geometry();
  }

  InvoluteGear InvoluteGear::from_diametral_pitch(const unsigned int      n_teeth,
                                                  const double            diametral_pitch,
                                                  const double            pressure_angle,
                                                  const ToothProportions &proportions)
  {
    require_entry(diametral_pitch > 0.0, "Diametral pitch", "the diametral pitch must be positive");
    return InvoluteGear(n_teeth, mm_per_inch / diametral_pitch, pressure_angle, proportions);
  }

  InvoluteGear InvoluteGear::from_pitch_or_module(const unsigned int      n_teeth,
                                                  const double            diametral_pitch,
                                                  const double            module,
                                                  const double            pressure_angle,
                                                  const ToothProportions &proportions)
  {
    return diametral_pitch > 0.
               ? from_diametral_pitch(n_teeth, diametral_pitch, pressure_angle, proportions)
               : InvoluteGear(n_teeth, module, pressure_angle, proportions);
  }

  double InvoluteGear::involute(const double angle)
  {
    return std::tan(angle) - angle;
  }

  double InvoluteGear::inverse_involute(const double value)
  {
    if (value <= 0.0)
      return 0.0;
    // inv(a) ~ a^3 / 3 for small a: start there (or near pi/2 for large values), then Newton
    // on inv(a) - value with inv'(a) = tan^2(a); inv is convex, so Newton from the right is
    // monotone. A bisection bracket [0, pi/2) guards the iteration.
    double lo = 0.0, hi = 0.5 * M_PI;
    double a = std::min(std::cbrt(3.0 * value), 1.4);
    if (involute(a) < value)
      a = 0.5 * (a + hi);
    for (unsigned int it = 0; it < 100; ++it)
    {
      const double f = involute(a) - value;
      if (f > 0.0)
        hi = a;
      else
        lo = a;
      const double t = std::tan(a);
      double       an = a - f / (t * t);
      if (!(an > lo && an < hi))
        an = 0.5 * (lo + hi);
      if (std::abs(an - a) <= 1e-15 * std::max(1.0, a))
        return an;
      a = an;
    }
    return a;
  }

  Point<2> InvoluteGear::involute_point(const double base_radius, const double roll_angle)
  {
    const double u = roll_angle;
    return Point<2>(base_radius * (std::cos(u) + u * std::sin(u)),
                    base_radius * (std::sin(u) - u * std::cos(u)));
  }

  double InvoluteGear::pitch_radius() const
  {
    return 0.5 * m * z;
  }

  double InvoluteGear::base_radius() const
  {
    return pitch_radius() * std::cos(alpha);
  }

  double InvoluteGear::tip_radius() const
  {
    return pitch_radius() + add;
  }

  double InvoluteGear::root_radius() const
  {
    return pitch_radius() - ded;
  }

  double InvoluteGear::circular_pitch() const
  {
    return M_PI * m;
  }

  double InvoluteGear::angular_pitch() const
  {
    return 2.0 * M_PI / z;
  }

  double InvoluteGear::pressure_angle_at(const double r) const
  {
    const double rb = base_radius();
    return (r <= rb) ? 0.0 : std::acos(rb / r);
  }

  double InvoluteGear::roll_angle_at(const double r) const
  {
    const double rb = base_radius();
    return (r <= rb) ? 0.0 : std::sqrt(r * r / (rb * rb) - 1.0);
  }

  double InvoluteGear::half_thickness_angle(const double r) const
  {
    // inv(alpha_r) = u - atan(u) with the roll angle u = tan(alpha_r); exact also at r = r_b.
    const double u = roll_angle_at(r);
    return s_p / (2.0 * pitch_radius()) + involute(alpha) - (u - std::atan(u));
  }

  double InvoluteGear::tooth_thickness(const double r) const
  {
    return 2.0 * r * half_thickness_angle(r);
  }

  Point<2> InvoluteGear::flank_point(const double r, const FlankSide side) const
  {
    const Point<2> p = polar_point(r, half_thickness_angle(r));
    return side == FlankSide::positive ? p : mirror(p);
  }

  Tensor<1, 2> InvoluteGear::flank_normal(const double r, const FlankSide side) const
  {
    // Positive flank: the involute's tangent point on the base circle is at polar angle
    // theta_T = beta_0 - u; the normal is the base-circle tangent direction e_perp(theta_T),
    // pointing counter-clockwise, i.e. away from the tooth.
    const double theta_t = tooth.base_half_angle - roll_angle_at(r);
    Tensor<1, 2> n;
    n[0] = -std::sin(theta_t);
    n[1] = std::cos(theta_t);
    if (side == FlankSide::negative)
      n[1] = -n[1];
    return n;
  }

  std::vector<Point<2>> InvoluteGear::flank(const FlankSide    side,
                                            const double       r_from,
                                            const double       r_to,
                                            const unsigned int n_points) const
  {
    require(n_points >= 2, "Involute gear", "a flank needs at least 2 points");
    const double tol = 1e-12 * tip_radius();
    require(std::min(r_from, r_to) >= root_radius() - tol
                && std::max(r_from, r_to) <= tip_radius() + tol,
            "Involute gear",
            "flank radii must lie between the root and the tip radius");
    std::vector<Point<2>> points;
    points.reserve(n_points);
    for (unsigned int j = 0; j < n_points; ++j)
      points.push_back(flank_point(r_from + (r_to - r_from) * j / (n_points - 1), side));
    return points;
  }

  void InvoluteGear::compute_tooth_geometry()
  {
    const double rb = base_radius(), rr = root_radius(), rt = tip_radius();

    tooth.base_half_angle = half_thickness_angle(rb);
    tooth.tip_half_angle = half_thickness_angle(rt);
    require_entry(
        tooth.tip_half_angle > 0.0,
        "Addendum",
        "the tooth is pointed below the tip circle (reduce the addendum or thicken the tooth)");
    require_entry(half_thickness_angle(rr) < M_PI / z,
                  "Tooth thickness",
                  "the teeth overlap at the root circle (tooth thickness too large)");

    if (rho_f == 0.0)
    {
      tooth.flank_start_radius = rr;
      tooth.root_land_angle = half_thickness_angle(rr);
      tooth.fillet_center = flank_point(rr, FlankSide::positive);
    }
    else
    {
      // The fillet circle lies in the tooth space, tangent to the root circle (centre at radius
      // rr + rho) and to the flank at radius r* (centre at P(r*) + rho n(r*)). Find r* by
      // bisection on f(r) = |P(r) + rho n(r)| - (rr + rho), which is negative at r = rr.
      const auto f = [&](const double r)
      {
        const Point<2> c
            = flank_point(r, FlankSide::positive) + rho_f * flank_normal(r, FlankSide::positive);
        return c.norm() - (rr + rho_f);
      };
      require_entry(
          f(rt) > 0.0,
          "Root fillet radius",
          "the root fillet radius is too large: the fillet does not meet the flank below the "
          "tip circle");
      double lo = rr, hi = rt;
      for (unsigned int it = 0; it < 200 && hi - lo > 1e-15 * rt; ++it)
      {
        const double mid = 0.5 * (lo + hi);
        (f(mid) < 0.0 ? lo : hi) = mid;
      }
      const double r_star = 0.5 * (lo + hi);
      tooth.flank_start_radius = r_star;
      tooth.fillet_center = flank_point(r_star, FlankSide::positive)
                            + rho_f * flank_normal(r_star, FlankSide::positive);
      tooth.root_land_angle = std::atan2(tooth.fillet_center[1], tooth.fillet_center[0]);
      require_entry(tooth.root_land_angle <= M_PI / z + 1e-12,
                    "Root fillet radius",
                    "the root fillet radius is too large: fillets of neighbouring teeth overlap");
      tooth.root_land_angle = std::min(tooth.root_land_angle, M_PI / z);
    }
    tooth.has_radial_flank = tooth.flank_start_radius < rb;
  }

  ToothOutline InvoluteGear::tooth_outline(const double max_segment_length,
                                           const double axis_angle) const
  {
    require(max_segment_length > 0.0, "Involute gear", "the segment length must be positive");
    const double   h = max_segment_length;
    const double   rb = base_radius(), rr = root_radius(), rt = tip_radius();
    const Point<2> origin;

    // Positive half H: from the tip point on the tooth axis to the middle of the next space.
    ToothOutline half;
    half.points.push_back(Point<2>(rt, 0.0));
    append_arc(half, origin, rt, 0.0, tooth.tip_half_angle, OutlinePart::tip_land, h);

    // Involute from the tip down to max(r*, r_b), equally spaced in arc length (~ u^2).
    const double u_tip = roll_angle_at(rt);
    const double u_low = roll_angle_at(std::max(tooth.flank_start_radius, rb));
    {
      const double       length = 0.5 * rb * (u_tip * u_tip - u_low * u_low);
      const unsigned int n = n_segments(length, h);
      for (unsigned int j = 1; j <= n; ++j)
      {
        const double u2 = u_tip * u_tip + (u_low * u_low - u_tip * u_tip) * j / n;
        const double r = rb * std::sqrt(1.0 + u2);
        half.points.push_back(
            flank_point(j == n ? std::max(tooth.flank_start_radius, rb) : r, FlankSide::positive));
        half.parts.push_back(OutlinePart::involute_flank);
      }
    }
    if (tooth.has_radial_flank)
      append_line(half,
                  half.points.back(),
                  flank_point(tooth.flank_start_radius, FlankSide::positive),
                  OutlinePart::radial_flank,
                  h);
    if (rho_f > 0.0)
    {
      const Point<2>     c = tooth.fillet_center;
      const Tensor<1, 2> a = half.points.back() - c;
      const Point<2>     q = polar_point(rr, tooth.root_land_angle);
      const Tensor<1, 2> b = q - c;
      const double       phi_a = std::atan2(a[1], a[0]);
      double             dphi = std::atan2(b[1], b[0]) - phi_a;
      dphi = std::remainder(dphi, 2.0 * M_PI);
      append_arc(half, c, rho_f, phi_a, phi_a + dphi, OutlinePart::root_fillet, h);
      half.points.back() = q; // exact tangency point
    }
    if (tooth.root_land_angle < M_PI / z)
      append_arc(half, origin, rr, tooth.root_land_angle, M_PI / z, OutlinePart::root_land, h);

    // Full tooth: mirrored half reversed (from -pi/z up to the axis), then the half itself.
    ToothOutline      outline;
    const std::size_t n_half = half.points.size();
    for (std::size_t j = n_half; j-- > 0;)
      outline.points.push_back(rotate(mirror(half.points[j]), axis_angle));
    for (std::size_t j = n_half - 1; j-- > 0;)
      outline.parts.push_back(half.parts[j]);
    for (std::size_t j = 1; j < n_half; ++j)
      outline.points.push_back(rotate(half.points[j], axis_angle));
    outline.parts.insert(outline.parts.end(), half.parts.begin(), half.parts.end());
    outline.closed = false;
    return outline;
  }

  ToothOutline InvoluteGear::gear_outline(const double max_segment_length,
                                          const double axis_angle) const
  {
    ToothOutline gear;
    for (unsigned int k = 0; k < z; ++k)
    {
      const ToothOutline tooth_k
          = tooth_outline(max_segment_length, axis_angle + k * angular_pitch());
      // Tooth k starts where tooth k-1 ended: drop the duplicate first point.
      const std::size_t first = (k == 0) ? 0 : 1;
      gear.points.insert(gear.points.end(), tooth_k.points.begin() + first, tooth_k.points.end());
      gear.parts.insert(gear.parts.end(), tooth_k.parts.begin(), tooth_k.parts.end());
    }
    // The last point coincides with the first one: close the outline instead.
    gear.points.pop_back();
    gear.closed = true;
    return gear;
  }
} // namespace ausroll::geometry
