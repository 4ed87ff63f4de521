#include <ausroll/contact/surfaces/ellipse.h>
#include <ausroll/core/exceptions.h>
#include <ausroll/core/parse_utilities.h>

#include <deal.II/base/numbers.h>
#include <deal.II/base/quadrature_lib.h>

#include <algorithm>
#include <cmath>

namespace ausroll::contact::surfaces
{
  using namespace dealii;

  namespace
  {
    constexpr double two_pi = 2. * numbers::PI;

    /** @p x wrapped into [0, @p period). */
    double wrap(const double x, const double period)
    {
      double r = std::fmod(x, period);
      if (r < 0.)
        r += period;
      return r >= period ? 0. : r;
    }

    /**
     * Closest point (x0, x1) of the ellipse (x0/e0)^2 + (x1/e1)^2 = 1, e0 >= e1 > 0, to the
     * first-quadrant point (y0, y1), y0, y1 >= 0 (see EllipseSurface for the method).
     */
    std::array<double, 2>
    closest_in_first_quadrant(const double e0, const double e1, const double y0, const double y1)
    {
      if (y1 > 0.)
      {
        if (y0 > 0.)
        {
          // with t = (u - 1) e1^2: x0 = r0 y0 / (u + r0 - 1), x1 = y1 / u, r0 = (e0/e1)^2, and u
          // the root of G(u) = (r0 z0 / (u + r0 - 1))^2 + (z1 / u)^2 - 1, z = y / e. u (not
          // t) is bisected: it keeps its relative precision when it is small (x near the axis).
          const double z0 = y0 / e0, z1 = y1 / e1, r0 = (e0 / e1) * (e0 / e1);
          const double g = z0 * z0 + z1 * z1 - 1.;
          if (g == 0.)
            return {{y0, y1}};
          const double n0 = r0 * z0, shift = r0 - 1.;
          double       lo = z1;                               // G(lo) >= 0
          double       hi = g < 0. ? 1. : std::hypot(n0, z1); // G(hi) <= 0
          double       u = 0.5 * (lo + hi);
          for (unsigned int it = 0; it < 400; ++it)
          {
            u = 0.5 * (lo + hi);
            if (u == lo || u == hi)
              break;
            const double q0 = n0 / (u + shift), q1 = z1 / u;
            const double G = q0 * q0 + q1 * q1 - 1.;
            if (G > 0.)
              lo = u;
            else if (G < 0.)
              hi = u;
            else
              break;
          }
          return {{r0 * y0 / (u + shift), y1 / u}};
        }
        // on the minor axis: the minor vertex
        return {{0., e1}};
      }
      // on the major axis: inside the evolute two closest points off the axis (the upper one),
      // otherwise the major vertex
      const double numerator = e0 * y0, denominator = e0 * e0 - e1 * e1;
      if (numerator < denominator)
      {
        const double xi = numerator / denominator; // x0 / e0
        return {{e0 * xi, e1 * std::sqrt(std::max(0., 1. - xi * xi))}};
      }
      return {{e0, 0.}};
    }
  } // namespace

  EllipseSurface::EllipseSurface(const Point<2> &center,
                                 const double    a,
                                 const double    b,
                                 const double    alpha,
                                 const bool      material_inside)
      : c(center)
      , a(a)
      , b(b)
      , cos_alpha(std::cos(alpha))
      , sin_alpha(std::sin(alpha))
      , inside(material_inside)
  {
    require(a > 0. && std::isfinite(a), "Semi-axis a", "must be positive");
    require(b > 0. && std::isfinite(b), "Semi-axis b", "must be positive");
    const double ratio = std::max(a / b, b / a);
    require(ratio <= 1000., "Semi-axis a", "a/b and b/a must not exceed 1000");
    const unsigned int n_panels = std::max(64u, 32u * static_cast<unsigned int>(std::ceil(ratio)));
    panel_width = two_pi / n_panels;
    cumulative.resize(n_panels + 1, 0.);
    const QGauss<1> gauss(8);
    for (unsigned int k = 0; k < n_panels; ++k)
    {
      double sum = 0.;
      for (unsigned int q = 0; q < gauss.size(); ++q)
        sum += gauss.weight(q) * speed((k + gauss.point(q)[0]) * panel_width);
      cumulative[k + 1] = cumulative[k] + sum * panel_width;
    }
    perimeter = cumulative.back();
  }

  double EllipseSurface::speed(const double phi) const
  {
    return std::hypot(a * std::sin(phi), b * std::cos(phi));
  }

  double EllipseSurface::arc_length(const double phi) const
  {
    const double       p = std::max(0., std::min(two_pi, phi));
    const unsigned int k = std::min(static_cast<unsigned int>(p / panel_width),
                                    static_cast<unsigned int>(cumulative.size()) - 2);
    const double       phi_k = k * panel_width, h = p - phi_k;
    const QGauss<1>    gauss(8);
    double             sum = 0.;
    for (unsigned int q = 0; q < gauss.size(); ++q)
      sum += gauss.weight(q) * speed(phi_k + gauss.point(q)[0] * h);
    return cumulative[k] + sum * h;
  }

  double EllipseSurface::angle_at_length(const double length) const
  {
    // panel holding the length, then Newton on arc_length(phi) = length kept in the panel
    const auto it = std::upper_bound(cumulative.begin() + 1, cumulative.end() - 1, length);
    const auto k = static_cast<unsigned int>(it - cumulative.begin()) - 1;
    double     lo = k * panel_width, hi = (k + 1) * panel_width;
    double phi = lo + (length - cumulative[k]) / (cumulative[k + 1] - cumulative[k]) * panel_width;
    for (unsigned int it_newton = 0; it_newton < 50; ++it_newton)
    {
      const double f = arc_length(phi) - length;
      if (f > 0.)
        hi = phi;
      else
        lo = phi;
      double next = phi - f / speed(phi);
      if (!(next > lo && next < hi))
        next = 0.5 * (lo + hi);
      if (std::abs(next - phi) <= 1e-16 * two_pi)
        return next;
      phi = next;
    }
    return phi;
  }

  double EllipseSurface::coordinate(const double phi) const
  {
    const double l = arc_length(wrap(phi, two_pi));
    return inside ? wrap(perimeter - l, perimeter) : wrap(l, perimeter);
  }

  SurfaceProjection<2> EllipseSurface::project(const Point<2> &x, const double max_distance) const
  {
    SurfaceProjection<2> result;
    // x in the ellipse frame: xi = R(-alpha) (x - c)
    const Tensor<1, 2> v = x - c;
    const double       xi_a = cos_alpha * v[0] + sin_alpha * v[1];
    const double       xi_b = -sin_alpha * v[0] + cos_alpha * v[1];
    if (std::hypot(xi_a, xi_b) - std::max(a, b) > max_distance)
      return result;

    // reflect into the first quadrant with the larger semi-axis first
    const bool            swap = a < b;
    const double          e0 = swap ? b : a, e1 = swap ? a : b;
    const double          y_a = std::abs(xi_a), y_b = std::abs(xi_b);
    std::array<double, 2> q = closest_in_first_quadrant(e0, e1, swap ? y_b : y_a, swap ? y_a : y_b);
    if (swap)
      std::swap(q[0], q[1]);
    const double p_a = xi_a < 0. ? -q[0] : q[0];
    const double p_b = xi_b < 0. ? -q[1] : q[1];

    // outward normal of the ellipse ~ (p_a / a^2, p_b / b^2); die normal out of the material
    Tensor<1, 2> m({p_a / (a * a), p_b / (b * b)});
    m /= m.norm();
    if (!inside)
      m = -m;
    const Tensor<1, 2> n(
        {cos_alpha * m[0] - sin_alpha * m[1], sin_alpha * m[0] + cos_alpha * m[1]});
    const Point<2> point(c[0] + cos_alpha * p_a - sin_alpha * p_b,
                         c[1] + sin_alpha * p_a + cos_alpha * p_b);

    result.gap = (x - point) * n;
    result.distance = std::abs(result.gap);
    if (result.distance > max_distance)
      return result;
    result.valid = true;
    result.point = point;
    result.normal = n;
    result.tangents[0] = Tensor<1, 2>({n[1], -n[0]});
    const double w = std::hypot(a * p_b / b, b * p_a / a); // speed at the point
    result.curvatures[0] = (inside ? 1. : -1.) * a * b / (w * w * w);
    result.coordinates[0] = coordinate(std::atan2(p_b / b, p_a / a));
    return result;
  }

  Point<2> EllipseSurface::point_at(const std::array<double, 1> &coordinates) const
  {
    const double s = wrap(coordinates[0], perimeter);
    const double phi = angle_at_length(inside ? wrap(perimeter - s, perimeter) : s);
    const double p_a = a * std::cos(phi), p_b = b * std::sin(phi);
    return Point<2>(c[0] + cos_alpha * p_a - sin_alpha * p_b,
                    c[1] + sin_alpha * p_a + cos_alpha * p_b);
  }

  void EllipseParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Center", "0, 0", Patterns::Anything(), "Centre of the ellipse.");
    prm.declare_entry("Semi-axis a",
                      "1",
                      Patterns::Double(0.),
                      "Semi-axis along the direction Rotation angle (mm).");
    prm.declare_entry("Semi-axis b", "1", Patterns::Double(0.), "Semi-axis across it (mm).");
    prm.declare_entry("Rotation angle",
                      "0",
                      Patterns::Double(),
                      "Direction of the a axis (degrees from +x, counter-clockwise).");
    prm.declare_entry("Material inside",
                      "true",
                      Patterns::Bool(),
                      "true for an oval roll or punch (die material inside), false for an "
                      "elliptic hole.");
  }

  void EllipseParameters::parse(ParameterHandler &prm, const std::string &path, const std::string &)
  {
    center = parse_point<2>(prm.get("Center"), path + "Center");
    semi_axis_a = prm.get_double("Semi-axis a");
    semi_axis_b = prm.get_double("Semi-axis b");
    rotation_angle = prm.get_double("Rotation angle");
    material_inside = prm.get_bool("Material inside");
    require(semi_axis_a > 0., path + "Semi-axis a", "must be positive");
    require(semi_axis_b > 0., path + "Semi-axis b", "must be positive");
  }

  std::unique_ptr<const RigidSurface<2>> EllipseParameters::create(const std::string &path) const
  {
    try
    {
      return std::make_unique<EllipseSurface>(
          center, semi_axis_a, semi_axis_b, rotation_angle * numbers::PI / 180., material_inside);
    }
    catch (const std::exception &e)
    {
      throw InputError(path + e.what());
    }
  }
} // namespace ausroll::contact::surfaces

AUSROLL_REGISTER_DIE_SHAPE(2,
                           ausroll::contact::surfaces::EllipseParameters,
                           "ellipse",
                           "Ellipse",
                           "a full ellipse (semi-axes, rotation angle)")
