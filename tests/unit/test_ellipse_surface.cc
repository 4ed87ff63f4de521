/**
 * @file test_ellipse_surface.cc
 * Unit tests of the elliptic die (contact::surfaces::EllipseSurface), the shape added through
 * the one-file-per-shape route: projection against a brute-force dense sampling of the ellipse,
 * x = x_proj + g n, the sign of the gap, the curvature at the vertices, the arc length, the
 * circle limit a = b against the circle shape, and the shape made from its `.prm` subsection.
 */
#include <ausroll/contact/contact_parameters.h>
#include <ausroll/contact/rigid_die.h>
#include <ausroll/contact/surfaces/circle.h>
#include <ausroll/contact/surfaces/ellipse.h>

#include <deal.II/base/numbers.h>

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <vector>

using ausroll::contact::SurfaceProjection;
using ausroll::contact::surfaces::CircleParameters;
using ausroll::contact::surfaces::EllipseSurface;
using dealii::Point;
using dealii::Tensor;

namespace
{
  constexpr double pi = dealii::numbers::PI;

  struct Ellipse
  {
    Point<2> c;
    double   a, b, alpha;
    bool     inside;

    /** Point at parametric angle phi. */
    Point<2> at(const double phi) const
    {
      const double p = a * std::cos(phi), q = b * std::sin(phi);
      return Point<2>(c[0] + std::cos(alpha) * p - std::sin(alpha) * q,
                      c[1] + std::sin(alpha) * p + std::cos(alpha) * q);
    }

    /** (p/a)^2 + (q/b)^2 of x in the ellipse frame (< 1 inside). */
    double level(const Point<2> &x) const
    {
      const Tensor<1, 2> v = x - c;
      const double       p = std::cos(alpha) * v[0] + std::sin(alpha) * v[1];
      const double       q = -std::sin(alpha) * v[0] + std::cos(alpha) * v[1];
      return (p / a) * (p / a) + (q / b) * (q / b);
    }

    EllipseSurface surface() const { return EllipseSurface(c, a, b, alpha, inside); }
  };

  /** n points evenly spaced in the parametric angle. */
  std::vector<Point<2>> samples(const Ellipse &e, const unsigned int n)
  {
    std::vector<Point<2>> p(n);
    for (unsigned int k = 0; k < n; ++k)
      p[k] = e.at(2. * pi * k / n);
    return p;
  }

  /** Distance from x to the ellipse by dense sampling (brute force). */
  double brute_force_distance(const std::vector<Point<2>> &samples, const Point<2> &x)
  {
    double d2 = std::numeric_limits<double>::infinity();
    for (const Point<2> &p : samples)
      d2 = std::min(d2, (x - p).norm_square());
    return std::sqrt(d2);
  }

  /** Query points around @p e: a grid over twice its box, the centre, points on and near the
      axes, and far points. */
  std::vector<Point<2>> query_points(const Ellipse &e)
  {
    std::vector<Point<2>> x;
    const double          r = 2. * std::max(e.a, e.b);
    for (int i = -6; i <= 6; ++i)
      for (int j = -6; j <= 6; ++j)
        x.emplace_back(e.c[0] + r * i / 6.3, e.c[1] + r * j / 6.1);
    const Tensor<1, 2> ea({std::cos(e.alpha), std::sin(e.alpha)});
    const Tensor<1, 2> eb({-std::sin(e.alpha), std::cos(e.alpha)});
    for (const double t : {0., 1e-12, 1e-6, 0.1, 0.5, 0.9, 0.999, 1., 1.001, 1.5, 3., 100.})
      for (const double sign : {1., -1.})
      {
        x.push_back(e.c + sign * t * e.a * ea); // on the a axis
        x.push_back(e.c + sign * t * e.b * eb); // on the b axis
        x.push_back(e.c + sign * t * e.a * ea + 1e-9 * eb);
      }
    return x;
  }
} // namespace

TEST(EllipseSurface, ProjectionAgainstDenseSampling)
{
  // Brute force: 400000 samples, spacing h <= L / 4e5 ~ 6e-5; the sampled distance exceeds the
  // true one by at most h^2 / (8 rho_min) + h^2 kappa_max ~ 1e-7 (rho, kappa of the ellipse), and
  // it is never smaller than the exact distance (up to rounding, 1e-12).
  const std::vector<Ellipse> ellipses{{Point<2>(1., -2.), 3., 1.2, 30. * pi / 180., true},
                                      {Point<2>(0., 0.), 1., 4., -70. * pi / 180., true},
                                      {Point<2>(-1., 0.5), 2.5, 2., 0., false}};
  for (const Ellipse &e : ellipses)
  {
    const EllipseSurface        surface = e.surface();
    const std::vector<Point<2>> dense = samples(e, 400000);
    for (const Point<2> &x : query_points(e))
    {
      const SurfaceProjection<2> p = surface.project(x);
      ASSERT_TRUE(p.valid);
      const double bf = brute_force_distance(dense, x);
      const double scale = std::max(1., x.distance(e.c));
      EXPECT_GE(bf, p.distance - 1e-12 * scale) << x;
      EXPECT_LE(bf, p.distance + 1e-7) << x;
      // the closest point lies on the ellipse
      EXPECT_NEAR(e.level(p.point), 1., 1e-13) << x;
      // x = x_proj + g n and the tangent is n rotated by -90 degrees
      const Point<2> back = p.point + p.gap * p.normal;
      EXPECT_NEAR(back[0], x[0], 1e-12 * scale) << x;
      EXPECT_NEAR(back[1], x[1], 1e-12 * scale) << x;
      EXPECT_NEAR(p.normal.norm(), 1., 1e-15);
      EXPECT_NEAR(p.tangents[0][0], p.normal[1], 1e-15);
      EXPECT_NEAR(p.tangents[0][1], -p.normal[0], 1e-15);
      EXPECT_DOUBLE_EQ(std::abs(p.gap), p.distance);
      // sign of the gap: inside the ellipse is die material when Material inside
      const double level = e.level(x);
      if (std::abs(level - 1.) > 1e-9)
        EXPECT_EQ(p.gap < 0., (level < 1.) == e.inside) << x << " gap " << p.gap;
      EXPECT_FALSE(p.at_edge || p.at_end);
      // the surface coordinate names the closest point
      EXPECT_LT(surface.point_at(p.coordinates).distance(p.point), 1e-12 * std::max(e.a, e.b)) << x;
      EXPECT_GE(p.coordinates[0], 0.);
      EXPECT_LT(p.coordinates[0], surface.total_length());
    }
  }
}

TEST(EllipseSurface, CurvatureAtVertices)
{
  for (const bool inside : {true, false})
  {
    const double         a = 3., b = 1.25;
    const EllipseSurface e(Point<2>(0.5, 0.25), a, b, 0., inside);
    const double         sign = inside ? 1. : -1.;
    // end of the a axis: radius of curvature b^2 / a, curvature a / b^2
    const SurfaceProjection<2> pa = e.project(Point<2>(0.5 + a + 0.7, 0.25));
    EXPECT_NEAR(pa.curvatures[0], sign * a / (b * b), 1e-13);
    EXPECT_NEAR(pa.point[0], 0.5 + a, 1e-15);
    EXPECT_NEAR(pa.gap, sign * 0.7, 1e-15);
    // end of the b axis: curvature b / a^2
    const SurfaceProjection<2> pb = e.project(Point<2>(0.5, 0.25 - b - 0.3));
    EXPECT_NEAR(pb.curvatures[0], sign * b / (a * a), 1e-13);
    EXPECT_NEAR(pb.point[1], 0.25 - b, 1e-15);
    EXPECT_NEAR(pb.normal[1], -sign, 1e-15);
  }
}

TEST(EllipseSurface, NearCentreAndOnAxes)
{
  const double         a = 2., b = 1.;
  const EllipseSurface e(Point<2>(0., 0.), a, b, 0., true);
  // on the minor axis the minor vertex is closest; at the centre too (distance b)
  for (const double y : {0., 1e-300, 1e-12, 0.5})
  {
    const SurfaceProjection<2> p = e.project(Point<2>(0., y));
    EXPECT_NEAR(p.point[0], 0., 1e-15);
    EXPECT_NEAR(p.point[1], b, 1e-15);
    EXPECT_NEAR(p.gap, -(b - y), 1e-15);
  }
  // on the major axis inside the evolute (|x| < (a^2 - b^2)/a = 1.5) two points are closest:
  // x_proj = (a^2 x / (a^2 - b^2), b sqrt(1 - (a x / (a^2 - b^2))^2)), the upper one taken
  for (const double x : {1e-300, 1e-9, 0.3, 1.2, -0.7})
  {
    const SurfaceProjection<2> p = e.project(Point<2>(x, 0.));
    const double               xi = a * x / (a * a - b * b);
    EXPECT_NEAR(p.point[0], a * xi, 1e-15);
    EXPECT_NEAR(p.point[1], b * std::sqrt(1. - xi * xi), 1e-15);
    EXPECT_LT(p.gap, 0.);
    EXPECT_NEAR(p.distance, std::hypot(x - p.point[0], p.point[1]), 1e-15);
  }
  // beyond the evolute the major vertex
  const SurfaceProjection<2> v = e.project(Point<2>(1.7, 0.));
  EXPECT_NEAR(v.point[0], a, 1e-15);
  EXPECT_NEAR(v.gap, -0.3, 1e-15);
  // a point just off the axis near the evolute: projection continuous, not stuck at the vertex
  const SurfaceProjection<2> w = e.project(Point<2>(1.4, 1e-10));
  EXPECT_NEAR(e.project(Point<2>(1.4, 0.)).point[1], w.point[1], 1e-6);
}

TEST(EllipseSurface, ArcLengthAndPeriod)
{
  // perimeter against the trapezoidal rule on the periodic integrand sqrt(a^2 sin^2 + b^2 cos^2)
  // (exponentially convergent: 20000 points are exact to rounding)
  for (const double ratio : {1., 2., 10., 200.})
  {
    const double         a = 1.5, b = a / ratio;
    const EllipseSurface e(Point<2>(0., 0.), a, b, 0.3, true);
    const unsigned int   n = 20000;
    double               trapezoid = 0.;
    for (unsigned int k = 0; k < n; ++k)
      trapezoid += std::hypot(a * std::sin(2. * pi * k / n), b * std::cos(2. * pi * k / n));
    trapezoid *= 2. * pi / n;
    EXPECT_NEAR(e.total_length(), trapezoid, 1e-13 * trapezoid) << "a/b = " << ratio;
    EXPECT_EQ(e.coordinate_periods()[0], e.total_length());
    // a quarter is a quarter of the perimeter; point_at wraps
    EXPECT_NEAR(e.arc_length(0.5 * pi), 0.25 * e.total_length(), 1e-13 * trapezoid);
    EXPECT_LT(e.point_at({{0.}}).distance(e.point_at({{e.total_length()}})), 1e-13);
    EXPECT_LT(e.point_at({{-0.1}}).distance(e.point_at({{e.total_length() - 0.1}})), 1e-13);
  }
  // material inside: travelled clockwise, s = 0 at the end of the a axis
  const EllipseSurface e(Point<2>(0., 0.), 2., 1., 0., true);
  EXPECT_NEAR(e.point_at({{0.}})[0], 2., 1e-15);
  EXPECT_LT(e.point_at({{0.25 * e.total_length()}}).distance(Point<2>(0., -1.)), 1e-13);
  const EllipseSurface hole(Point<2>(0., 0.), 2., 1., 0., false);
  EXPECT_LT(hole.point_at({{0.25 * hole.total_length()}}).distance(Point<2>(0., 1.)), 1e-13);
}

TEST(EllipseSurface, CircleLimitEqualsCircleShape)
{
  // a = b = r: the ellipse and the circle shape (a CurveChain arc) agree in every field
  for (const bool inside : {true, false})
  {
    CircleParameters circle_parameters;
    circle_parameters.center = Point<2>(0.75, -0.5);
    circle_parameters.radius = 2.;
    circle_parameters.material_inside = inside;
    const auto           circle = circle_parameters.create("Contact/Die 0/Circle/");
    const EllipseSurface ellipse(Point<2>(0.75, -0.5), 2., 2., 0., inside);
    EXPECT_NEAR(ellipse.total_length(), circle->coordinate_periods()[0], 1e-12);
    for (int i = -7; i <= 7; ++i)
      for (int j = -7; j <= 7; ++j)
      {
        const Point<2>             x(0.75 + 0.61 * i + 0.013, -0.5 + 0.57 * j + 0.007);
        const SurfaceProjection<2> pc = circle->project(x), pe = ellipse.project(x);
        EXPECT_NEAR(pe.gap, pc.gap, 1e-12) << x;
        EXPECT_NEAR(pe.point.distance(pc.point), 0., 1e-12) << x;
        EXPECT_NEAR((pe.normal - pc.normal).norm(), 0., 1e-12) << x;
        EXPECT_NEAR((pe.tangents[0] - pc.tangents[0]).norm(), 0., 1e-12) << x;
        EXPECT_NEAR(pe.curvatures[0], pc.curvatures[0], 1e-12) << x;
        // s in [0, L): compare modulo the period (points near s = 0 may sit at either end)
        const double L = ellipse.total_length();
        const double ds = std::remainder(pe.coordinates[0] - pc.coordinates[0], L);
        EXPECT_NEAR(ds, 0., 1e-12) << x;
        EXPECT_LT(ellipse.point_at({{1.3 * i}}).distance(circle->point_at({{1.3 * i}})), 1e-12);
      }
  }
}

TEST(EllipseSurface, SearchDistance)
{
  const EllipseSurface e(Point<2>(0., 0.), 2., 1., 0.4, true);
  EXPECT_FALSE(e.project(Point<2>(10., 0.), 1.).valid); // rejected by the bounding circle
  EXPECT_FALSE(e.project(Point<2>(0., 2.5), 1.).valid); // 1.3 from the surface
  EXPECT_TRUE(e.project(Point<2>(0., 1.5), 1.).valid);
  EXPECT_ANY_THROW(EllipseSurface(Point<2>(), 0., 1., 0., true));
  EXPECT_ANY_THROW(EllipseSurface(Point<2>(), 1., 1e-4, 0., true)); // aspect ratio > 1000
}

TEST(EllipseSurface, FromItsParameterSubsection)
{
  // the factory route: Shape = ellipse and subsection `Ellipse` of `Contact/Die 0`
  dealii::ParameterHandler prm;
  ausroll::contact::ContactParameters::declare_parameters(prm);
  std::istringstream in("subsection Contact\n set Number of dies = 1\n subsection Die 0\n"
                        "  set Shape = ellipse\n  subsection Ellipse\n   set Center = 1, 2\n"
                        "   set Semi-axis a = 3\n   set Semi-axis b = 1\n"
                        "   set Rotation angle = 90\n  end\n end\nend\n");
  prm.parse_input(in, "test", "", false);
  ausroll::contact::ContactParameters p;
  p.parse_parameters(prm, "");
  ASSERT_EQ(p.dies.size(), 1u);
  EXPECT_EQ(p.dies[0].surface_path, "Contact/Die 0/Ellipse/");
  const ausroll::contact::RigidDie<2> die(p.dies[0], 0);
  EXPECT_EQ(die.surface().name(), "ellipse");
  // the a axis along +y: the top vertex (1, 5), curvature a / b^2 = 3
  const SurfaceProjection<2> top = die.surface().project(Point<2>(1., 6.));
  EXPECT_NEAR(top.point[1], 5., 1e-14);
  EXPECT_NEAR(top.curvatures[0], 3., 1e-12);
  EXPECT_NEAR(die.die_surface().project(Point<2>(1., 6.)).coordinates[0], 0., 1e-12);
  EXPECT_TRUE(die.die_surface().is_closed());
  // an invalid subsection entry names its full path
  std::istringstream bad("subsection Contact\n subsection Die 0\n  subsection Ellipse\n"
                         "   set Semi-axis b = 0\n  end\n end\nend\n");
  prm.parse_input(bad, "test", "", false);
  try
  {
    p.parse_parameters(prm, "");
    FAIL() << "no error";
  }
  catch (const std::exception &e)
  {
    EXPECT_EQ(std::string(e.what()), "Contact/Die 0/Ellipse/Semi-axis b: must be positive");
  }
}
