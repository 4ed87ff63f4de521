/**
 * @file test_surfaces_3d.cc
 * Unit tests of the 3D rigid surfaces (contact/surfaces/): plane, finite cylinder, torus,
 * revolved profile, extruded profile, and their parameter subsections.
 *
 * References and tolerances:
 * - Brute force: the surface is sampled densely (independently of the projection code: explicit
 *   parametrisations, or CurveChain::point_at() along the chain) and the smallest sample distance
 *   d_s compared with the projection's distance d. A projection onto the true closest point
 *   satisfies d <= d_s (every sample is a surface point; 1e-9 for rounding) and d_s - d <= delta,
 *   delta = the largest distance of a surface point from its nearest sample (half the diagonal of
 *   a sampling cell, stated per test). The gap sign is compared with an independent inside test
 *   (the solid's inequalities, or a point-in-polygon test of the sampled chain) for points farther
 *   than delta from the surface.
 * - Frame: |n| = 1, |t_i| = 1, t_i . n = 0, t_1 . t_2 = 0, t_1 x t_2 = n, x = x_proj + g n,
 *   |g| = distance, all to 1e-12 (relative to the size of x).
 * - Curvatures: the analytic values, and a central difference of the normal along each tangent
 *   on the surface (kappa_i = t_i . dn/ds_i, step 1e-5: truncation ~ 1e-10 kappa, rounding
 *   ~ 1e-11 / 1e-5), to 1e-5.
 * - Equivalences (revolved line chain = cylinder, revolved circle = torus, extruded circle =
 *   cylinder): every output to 1e-12 (the same arithmetic up to rounding).
 * - Continuity: the signed gap of a closed solid is a signed distance, hence 1-Lipschitz:
 *   |g(x) - g(y)| <= |x - y| (+1e-12) for pairs of close points around edges; along a path
 *   outside an edge the projected point and the normal move continuously.
 */
#include <ausroll/contact/surfaces/arc_line.h>
#include <ausroll/contact/surfaces/circle.h>
#include <ausroll/contact/surfaces/cone.h>
#include <ausroll/contact/surfaces/extruded_profile.h>
#include <ausroll/contact/surfaces/finite_cylinder.h>
#include <ausroll/contact/surfaces/flat.h>
#include <ausroll/contact/surfaces/involute_gear.h>
#include <ausroll/contact/surfaces/plane.h>
#include <ausroll/contact/surfaces/polyline.h>
#include <ausroll/contact/surfaces/revolved_profile.h>
#include <ausroll/contact/surfaces/surface_factory.h>
#include <ausroll/contact/surfaces/torus.h>
#include <ausroll/core/exceptions.h>
#include <ausroll/geometry/curve_chain.h>
#include <ausroll/geometry/involute_gear.h>

#include <deal.II/base/numbers.h>
#include <deal.II/base/parameter_handler.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <vector>

using namespace ausroll::contact;
using namespace ausroll::contact::surfaces;
using ausroll::geometry::CurveChain;
using ausroll::geometry::CurveSegment;
using dealii::Point;
using dealii::Tensor;
namespace numbers = dealii::numbers;

namespace
{
  Tensor<1, 3> vec(const double x, const double y, const double z)
  {
    return Tensor<1, 3>({x, y, z});
  }

  /** Frame and consistency checks that hold for every projection. */
  void expect_frame(const Point<3> &x, const SurfaceProjection<3> &p)
  {
    ASSERT_TRUE(p.valid);
    const double tol = 1e-12 * std::max(1., x.norm());
    EXPECT_NEAR(p.normal.norm(), 1., 1e-12);
    EXPECT_NEAR(p.tangents[0].norm(), 1., 1e-12);
    EXPECT_NEAR(p.tangents[1].norm(), 1., 1e-12);
    EXPECT_NEAR(p.tangents[0] * p.normal, 0., 1e-12);
    EXPECT_NEAR(p.tangents[1] * p.normal, 0., 1e-12);
    EXPECT_NEAR(p.tangents[0] * p.tangents[1], 0., 1e-12);
    EXPECT_LE((cross_product_3d(p.tangents[0], p.tangents[1]) - p.normal).norm(), 1e-12);
    EXPECT_LE((x - (p.point + p.gap * p.normal)).norm(), tol)
        << "x = " << x << " x_proj = " << p.point << " g = " << p.gap;
    EXPECT_NEAR(p.distance, std::abs(p.gap), tol);
  }

  /** Uniform random points in the box [lo, hi]. */
  std::vector<Point<3>>
  random_points(const Point<3> &lo, const Point<3> &hi, const unsigned int n, const unsigned seed)
  {
    std::mt19937                           rng(seed);
    std::uniform_real_distribution<double> u(0., 1.);
    std::vector<Point<3>>                  pts;
    for (unsigned int i = 0; i < n; ++i)
    {
      Point<3> p;
      for (unsigned int d = 0; d < 3; ++d)
        p[d] = lo[d] + (hi[d] - lo[d]) * u(rng);
      pts.push_back(p);
    }
    return pts;
  }

  /**
   * Brute-force comparison: @p samples are surface points with covering radius @p delta;
   * @p inside the independent inside test; @p lower_tol the tolerance of d <= d_s.
   */
  void expect_brute_force(const RigidSurface<3>                       &surface,
                          const std::vector<Point<3>>                 &samples,
                          const double                                 delta,
                          const std::vector<Point<3>>                 &queries,
                          const std::function<bool(const Point<3> &)> &inside,
                          const double                                 lower_tol = 1e-9)
  {
    unsigned int n_sign = 0;
    for (const Point<3> &x : queries)
    {
      double d2 = std::numeric_limits<double>::infinity();
      for (const Point<3> &s : samples)
        d2 = std::min(d2, (x - s).norm_square());
      const double               ds = std::sqrt(d2);
      const SurfaceProjection<3> p = surface.project(x);
      expect_frame(x, p);
      EXPECT_LE(p.distance, ds + lower_tol) << "x = " << x;
      EXPECT_LE(ds - p.distance, delta) << "x = " << x;
      if (ds > 2. * delta)
      {
        EXPECT_EQ(p.gap < 0., inside(x)) << "x = " << x << " gap " << p.gap;
        ++n_sign;
      }
      // the search band
      if (p.distance > 1e-6)
      {
        EXPECT_FALSE(surface.project(x, 0.5 * p.distance).valid);
        EXPECT_TRUE(surface.project(x, 2. * p.distance).valid);
      }
    }
    EXPECT_GT(n_sign, queries.size() / 2); // the sign was checked for most points
  }

  /**
   * Principal curvatures by central differences of the normal along each tangent at the
   * projection of @p x (on the surface, away from edges).
   */
  void expect_curvatures_by_differences(const RigidSurface<3> &surface, const Point<3> &x)
  {
    const SurfaceProjection<3> p = surface.project(x);
    ASSERT_TRUE(p.valid);
    if (p.at_edge || p.at_end)
      return;
    const double eps = 1e-5;
    for (unsigned int i = 0; i < 2; ++i)
    {
      const SurfaceProjection<3> a = surface.project(p.point + eps * p.tangents[i]);
      const SurfaceProjection<3> b = surface.project(p.point - eps * p.tangents[i]);
      if (a.at_edge || b.at_edge)
        continue;
      const Tensor<1, 3> dn = (a.normal - b.normal) / (2. * eps);
      EXPECT_NEAR(dn * p.tangents[i], p.curvatures[i], 1e-5) << "x = " << x << " i = " << i;
      EXPECT_NEAR(dn * p.tangents[1 - i], 0., 1e-5) << "x = " << x << " i = " << i;
    }
  }

  /** Samples of a surface of revolution of @p chain (radius at most @p r_max): covering radius. */
  double sample_revolved(const CurveChain      &chain,
                         const double           ds,
                         const unsigned int     n_theta,
                         const double           r_max,
                         std::vector<Point<3>> &samples)
  {
    const double length = chain.total_length();
    const auto   n_s = static_cast<unsigned int>(std::ceil(length / ds));
    for (unsigned int i = 0; i <= n_s; ++i)
    {
      const Point<2> q = chain.point_at(chain.s_begin() + length * i / n_s);
      for (unsigned int k = 0; k < n_theta; ++k)
      {
        const double theta = 2. * numbers::PI * k / n_theta;
        samples.emplace_back(q[0] * std::cos(theta), q[0] * std::sin(theta), q[1]);
      }
    }
    return 0.5 * std::hypot(length / n_s, 2. * numbers::PI * r_max / n_theta);
  }

  /** Polygon through the chain (every segment end a vertex, curved segments sampled). */
  std::vector<Point<2>> chain_polygon(const CurveChain &chain, const double ds)
  {
    std::vector<Point<2>> poly;
    for (unsigned int i = 0; i < chain.n_segments(); ++i)
    {
      const CurveSegment &seg = chain.segment(i);
      const unsigned int  n
          = seg.type() == CurveSegment::Type::line
                ? 1
                : std::max(1u, static_cast<unsigned int>(std::ceil(seg.length() / ds)));
      for (unsigned int k = 0; k < n; ++k)
        poly.push_back(seg.point(seg.u_begin() + seg.length() * k / n));
    }
    if (!chain.is_closed())
      poly.push_back(chain.segment(chain.n_segments() - 1).end_point());
    return poly;
  }

  /**
   * The part of a star-shaped closed chain (every ray from the origin meets it once, as a gear
   * without undercut) within the polar angles (-@p max_angle, @p max_angle), closed through the
   * origin: a polygon for the inside test of points in that sector.
   */
  std::vector<Point<2>>
  star_sector_polygon(const CurveChain &chain, const double ds, const double max_angle)
  {
    std::vector<std::pair<double, Point<2>>> pts;
    for (const Point<2> &q : chain_polygon(chain, ds))
      if (std::abs(std::atan2(q[1], q[0])) < max_angle)
        pts.emplace_back(std::atan2(q[1], q[0]), q);
    std::sort(
        pts.begin(), pts.end(), [](const auto &a, const auto &b) { return a.first < b.first; });
    std::vector<Point<2>> poly{Point<2>()};
    for (const auto &p : pts)
      poly.push_back(p.second);
    return poly;
  }

  /** Even-odd point-in-polygon test. */
  bool in_polygon(const std::vector<Point<2>> &poly, const double x, const double y)
  {
    bool              in = false;
    const std::size_t n = poly.size();
    for (std::size_t i = 0, j = n - 1; i < n; j = i++)
      if ((poly[i][1] > y) != (poly[j][1] > y)
          && x < (poly[j][0] - poly[i][0]) * (y - poly[i][1]) / (poly[j][1] - poly[i][1])
                     + poly[i][0])
        in = !in;
    return in;
  }

  /** A rotation of the canonical frame used to place shapes obliquely. */
  const Point<3>     oblique_origin(1.5, -2., 0.75);
  const Tensor<1, 3> oblique_axis = vec(1., 2., 2.) / 3.;
  const Tensor<1, 3> oblique_reference = vec(1., 0., 0.);

  /** Expect two projections to agree to 1e-12 (relative to @p scale). */
  void expect_same(const SurfaceProjection<3> &a,
                   const SurfaceProjection<3> &b,
                   const double                scale,
                   const bool                  tangents = true,
                   const bool                  coordinates = true)
  {
    ASSERT_TRUE(a.valid && b.valid);
    const double tol = 1e-12 * scale;
    EXPECT_LE((a.point - b.point).norm(), tol);
    EXPECT_NEAR(a.gap, b.gap, tol);
    EXPECT_LE((a.normal - b.normal).norm(), 1e-12);
    if (tangents)
      for (unsigned int i = 0; i < 2; ++i)
        EXPECT_LE((a.tangents[i] - b.tangents[i]).norm(), 1e-12);
    for (unsigned int i = 0; i < 2; ++i)
      EXPECT_NEAR(
          a.curvatures[i], b.curvatures[i], 1e-12 * std::max(1., std::abs(a.curvatures[i])));
    if (coordinates)
      for (unsigned int i = 0; i < 2; ++i)
        EXPECT_NEAR(a.coordinates[i], b.coordinates[i], tol);
    EXPECT_EQ(a.at_edge, b.at_edge);
    EXPECT_EQ(a.at_end, b.at_end);
  }
} // namespace

// ============================================================================ plane
TEST(Surfaces3D, PlaneInfiniteIsTheHalfSpace)
{
  const Tensor<1, 3> n = vec(1., 2., 2.) / 3.;
  const Point<3>     p0(1., 2., 3.);
  const Plane        plane(p0, 3. * n, vec(0., 0., 1.));
  for (const Point<3> &x : random_points(Point<3>(-5, -5, -5), Point<3>(5, 5, 5), 200, 1))
  {
    const SurfaceProjection<3> p = plane.project(x);
    expect_frame(x, p);
    EXPECT_NEAR(p.gap, (x - p0) * n, 1e-12 * x.norm() + 1e-12);
    EXPECT_LE((p.normal - n).norm(), 1e-14);
    EXPECT_EQ(p.curvatures[0], 0.);
    EXPECT_EQ(p.curvatures[1], 0.);
    EXPECT_FALSE(p.at_edge || p.at_end);
    // t_1 is the part of the first tangent orthogonal to n
    const Tensor<1, 3> t1 = vec(0., 0., 1.) - n[2] * n;
    EXPECT_LE((p.tangents[0] - t1 / t1.norm()).norm(), 1e-14);
    EXPECT_NEAR(p.coordinates[0], (p.point - p0) * p.tangents[0], 1e-12);
    EXPECT_NEAR(p.coordinates[1], (p.point - p0) * p.tangents[1], 1e-12);
  }
}

TEST(Surfaces3D, PlaneRectangleAgainstBruteForce)
{
  // rectangle 4 x 2 in an oblique plane; samples every 0.01: delta = 0.005 sqrt(2)
  const Tensor<1, 3>         n = vec(1., 2., 2.) / 3.;
  const Point<3>             p0(0.5, 0.5, 0.5);
  const Plane                plane(p0, n, vec(1., 0., 0.), 2., 1.);
  const SurfaceProjection<3> c = plane.project(p0 + n);
  const Tensor<1, 3>         t1 = c.tangents[0], t2 = c.tangents[1];
  std::vector<Point<3>>      samples;
  const double               h = 0.01;
  for (int i = -200; i <= 200; ++i)
    for (int j = -100; j <= 100; ++j)
      samples.push_back(p0 + (i * h) * t1 + (j * h) * t2);
  const double delta = 0.5 * std::sqrt(2.) * h * 1.0001;
  expect_brute_force(plane,
                     samples,
                     delta,
                     random_points(Point<3>(-3, -3, -3), Point<3>(4, 4, 4), 60, 2),
                     [&](const Point<3> &x) { return (x - p0) * n < 0.; });
  // beyond the rectangle: an end, the normal points from its boundary to x
  const Point<3>             x = p0 + 3. * t1 + 0.5 * n;
  const SurfaceProjection<3> p = plane.project(x);
  EXPECT_TRUE(p.at_end && p.at_edge);
  EXPECT_LE((p.point - (p0 + 2. * t1)).norm(), 1e-12);
  EXPECT_NEAR(p.gap, std::hypot(1., 0.5), 1e-12);
  EXPECT_NEAR(plane.project(p0 + 3. * t1 - 0.5 * n).gap, -std::hypot(1., 0.5), 1e-12);
}

// ============================================================================ cylinder
namespace
{
  /** Independent inside test of the rounded cylinder (canonical frame). */
  bool in_cylinder(const double r, const double z, const double R, const double h, const double re)
  {
    const double a = R - re, b = h - re, v = std::abs(z);
    return (r <= a && v <= h) || (r <= R && v <= b) || std::hypot(r - a, v - b) <= re;
  }

  /** The meridian profile of the cylinder as a CurveChain (for sampling and comparison). */
  CurveChain cylinder_profile(const double R, const double h, const double re)
  {
    const std::vector<Point<2>> pts{
        Point<2>(0., h), Point<2>(R, h), Point<2>(R, -h), Point<2>(0., -h)};
    return re > 0. ? arc_line_chain(pts, {re}) : polyline_chain(pts);
  }
} // namespace

TEST(Surfaces3D, CylinderAgainstBruteForce)
{
  const double R = 5., w = 4., h = 2.;
  for (const double re : {0., 1.})
  {
    const FiniteCylinder  cyl(oblique_origin, oblique_axis, R, w, re, oblique_reference);
    const Frame3D         frame(oblique_origin, oblique_axis, oblique_reference);
    std::vector<Point<3>> canonical;
    const double          delta
        = 1.0001 * sample_revolved(cylinder_profile(R, h, re), 0.02, 1600, R, canonical);
    std::vector<Point<3>> samples;
    for (const Point<3> &s : canonical)
      samples.push_back(frame.to_local(s));
    std::vector<Point<3>> queries;
    for (const Point<3> &q : random_points(Point<3>(-7, -7, -4), Point<3>(7, 7, 4), 80, 3 + re))
      queries.push_back(frame.to_local(q));
    queries.push_back(frame.to_local(Point<3>(0., 0., 0.5)));  // on the axis inside
    queries.push_back(frame.to_local(Point<3>(0., 0., 3.)));   // on the axis outside
    queries.push_back(frame.to_local(Point<3>(0., 0., -0.1))); // on the axis inside
    expect_brute_force(cyl,
                       samples,
                       delta,
                       queries,
                       [&](const Point<3> &x)
                       {
                         const Point<3> xi = frame.to_canonical(x);
                         return in_cylinder(std::hypot(xi[0], xi[1]), xi[2], R, h, re);
                       });
  }
}

TEST(Surfaces3D, CylinderAnalyticValues)
{
  const double         R = 5., w = 4., re = 1.;
  const FiniteCylinder cyl(Point<3>(), vec(0., 0., 1.), R, w, re);
  // mantle: n = e_r, t_1 = -e_z, t_2 = e_theta, curvatures (0, 1/R)
  const double               th = 0.7;
  const Point<3>             x(6. * std::cos(th), 6. * std::sin(th), 0.5);
  const SurfaceProjection<3> m = cyl.project(x);
  expect_frame(x, m);
  EXPECT_NEAR(m.gap, 1., 1e-14);
  EXPECT_LE((m.normal - vec(std::cos(th), std::sin(th), 0.)).norm(), 1e-14);
  EXPECT_LE((m.tangents[0] - vec(0., 0., -1.)).norm(), 1e-14);
  EXPECT_NEAR(m.curvatures[0], 0., 1e-14);
  EXPECT_NEAR(m.curvatures[1], 1. / R, 1e-14);
  EXPECT_NEAR(m.coordinates[0], 4. + 0.5 * numbers::PI + 0.5, 1e-13); // a + pi re / 2 + (b - z)
  EXPECT_NEAR(m.coordinates[1], th, 1e-14);
  // upper face: n = e_z, t_1 = e_r, curvatures 0, s = r
  const SurfaceProjection<3> f = cyl.project(Point<3>(1., 2., 3.));
  EXPECT_NEAR(f.gap, 1., 1e-14);
  EXPECT_NEAR(f.coordinates[0], std::sqrt(5.), 1e-14);
  EXPECT_EQ(f.curvatures[0], 0.);
  // rim: at 45 degrees in the meridian plane, curvatures (1/r_e, n_r / r)
  const double               c = std::sqrt(0.5);
  const SurfaceProjection<3> e = cyl.project(Point<3>(4. + 2. * c, 0., 1. + 2. * c));
  EXPECT_NEAR(e.gap, 1., 1e-14);
  EXPECT_NEAR(e.curvatures[0], 1. / re, 1e-14);
  EXPECT_NEAR(e.curvatures[1], c / (4. + c), 1e-14);
  EXPECT_FALSE(e.at_edge);
  // sharp cylinder: the rim is an edge
  const FiniteCylinder       sharp(Point<3>(), vec(0., 0., 1.), R, w, 0.);
  const SurfaceProjection<3> s = sharp.project(Point<3>(6., 0., 3.));
  EXPECT_TRUE(s.at_edge);
  EXPECT_NEAR(s.gap, std::sqrt(2.), 1e-14);
  EXPECT_EQ(s.curvatures[0], 0.);
  EXPECT_EQ(s.curvatures[1], 0.);
  // a point on the axis inside a long cylinder projects onto the mantle (theta = 0)
  const FiniteCylinder       tall(Point<3>(), vec(0., 0., 1.), 1., 10.);
  const SurfaceProjection<3> a = tall.project(Point<3>(0., 0., 0.));
  EXPECT_NEAR(a.gap, -1., 1e-14);
  EXPECT_LE((a.point - Point<3>(1., 0., 0.)).norm(), 1e-14);
  // bad sizes name the entry
  EXPECT_THROW(FiniteCylinder(Point<3>(), vec(0., 0., 1.), 1., 1., 0.6), ausroll::EntryError);
  EXPECT_THROW(FiniteCylinder(Point<3>(), vec(0., 0., 1.), -1., 1.), ausroll::EntryError);
}

// ============================================================================ torus
TEST(Surfaces3D, TorusAgainstBruteForce)
{
  const double          R = 6., rho = 2.;
  const Torus           torus(oblique_origin, oblique_axis, R, rho, oblique_reference);
  const Frame3D         frame(oblique_origin, oblique_axis, oblique_reference);
  std::vector<Point<3>> canonical;
  const double          delta
      = 1.0001
        * sample_revolved(circle_chain(Point<2>(R, 0.), rho), 0.02, 2400, R + rho, canonical);
  std::vector<Point<3>> samples, queries;
  for (const Point<3> &s : canonical)
    samples.push_back(frame.to_local(s));
  for (const Point<3> &q : random_points(Point<3>(-9, -9, -3), Point<3>(9, 9, 3), 80, 5))
    queries.push_back(frame.to_local(q));
  queries.push_back(frame.to_local(Point<3>(0., 0., 1.))); // on the axis
  expect_brute_force(torus,
                     samples,
                     delta,
                     queries,
                     [&](const Point<3> &x)
                     {
                       const Point<3> xi = frame.to_canonical(x);
                       return std::pow(std::hypot(xi[0], xi[1]) - R, 2) + xi[2] * xi[2]
                              <= rho * rho;
                     });
}

TEST(Surfaces3D, TorusCurvaturesAreTheStandardOnes)
{
  // kappa_1 = 1/rho, kappa_2 = cos(phi) / (R + rho cos(phi)), phi the angle of the normal from e_r
  const double R = 116.6, rho = 2.03;
  const Torus  torus(Point<3>(), vec(0., 0., 1.), R, rho);
  for (const double phi : {0., 0.4, 1.3, 2., -2.7, 3.})
    for (const double theta : {0., 1., -2.5})
    {
      const double   g = phi == 0. ? -0.5 : 0.7; // inside and outside
      const double   r = R + (rho + g) * std::cos(phi);
      const Point<3> x(r * std::cos(theta), r * std::sin(theta), (rho + g) * std::sin(phi));
      const SurfaceProjection<3> p = torus.project(x);
      expect_frame(x, p);
      EXPECT_NEAR(p.gap, g, 1e-12);
      EXPECT_NEAR(p.curvatures[0], 1. / rho, 1e-12);
      EXPECT_NEAR(p.curvatures[1], std::cos(phi) / (R + rho * std::cos(phi)), 1e-12);
      double s = -rho * phi;
      if (s < 0.)
        s += 2. * numbers::PI * rho;
      EXPECT_NEAR(p.coordinates[0], s, 1e-12);
      EXPECT_NEAR(p.coordinates[1], theta, 1e-12);
      expect_curvatures_by_differences(torus, x);
    }
  EXPECT_THROW(Torus(Point<3>(), vec(0., 0., 1.), 1., 1.), ausroll::EntryError);
}

// ============================================================================ revolved profile
TEST(Surfaces3D, RevolvedLineChainIsTheCylinder)
{
  const double R = 5., w = 4., h = 2.;
  for (const double re : {0., 1.})
  {
    const FiniteCylinder  cyl(oblique_origin, oblique_axis, R, w, re, oblique_reference);
    const RevolvedProfile rev(
        cylinder_profile(R, h, re), oblique_origin, oblique_axis, oblique_reference);
    const Frame3D frame(oblique_origin, oblique_axis, oblique_reference);
    for (const Point<3> &q : random_points(Point<3>(-7, -7, -4), Point<3>(7, 7, 4), 400, 7))
    {
      const Point<3> x = frame.to_local(q);
      expect_same(cyl.project(x), rev.project(x), 10.);
    }
    for (const Point<3> &q : {Point<3>(0., 0., 3.), Point<3>(0., 0., -0.5), Point<3>(0., 0., 1.5)})
      expect_same(cyl.project(frame.to_local(q)), rev.project(frame.to_local(q)), 10.);
  }
}

TEST(Surfaces3D, RevolvedCircleIsTheTorus)
{
  const double          R = 6., rho = 2.;
  const Torus           torus(oblique_origin, oblique_axis, R, rho, oblique_reference);
  const RevolvedProfile rev(
      circle_chain(Point<2>(R, 0.), rho), oblique_origin, oblique_axis, oblique_reference);
  const Frame3D frame(oblique_origin, oblique_axis, oblique_reference);
  for (const Point<3> &q : random_points(Point<3>(-9, -9, -3), Point<3>(9, 9, 3), 400, 8))
  {
    const Point<3>             x = frame.to_local(q);
    const SurfaceProjection<3> a = torus.project(x), b = rev.project(x);
    expect_same(a, b, 10., true, false);
    // s agrees modulo the profile length 2 pi rho
    const double L = 2. * numbers::PI * rho,
                 ds = std::remainder(a.coordinates[0] - b.coordinates[0], L);
    EXPECT_NEAR(ds, 0., 1e-12);
    EXPECT_NEAR(a.coordinates[1], b.coordinates[1], 1e-12);
  }
}

TEST(Surfaces3D, RevolvedBarrelAndConeAgainstBruteForce)
{
  // barrel roll: faces through the axis, conical flanks, filleted corners; double cone: two
  // vertices on the axis (edges) and a sharp rim
  const std::vector<Point<2>> barrel{
      Point<2>(0., 2.), Point<2>(4., 2.), Point<2>(5., 0.), Point<2>(4., -2.), Point<2>(0., -2.)};
  const std::vector<Point<2>> cone{Point<2>(0., 3.), Point<2>(4., 0.), Point<2>(0., -3.)};
  for (const bool is_barrel : {true, false})
  {
    const std::vector<Point<2>> &pts = is_barrel ? barrel : cone;
    const CurveChain      chain = is_barrel ? arc_line_chain(pts, {0.5}) : polyline_chain(pts);
    const RevolvedProfile rev(chain, oblique_origin, oblique_axis, oblique_reference);
    const Frame3D         frame(oblique_origin, oblique_axis, oblique_reference);
    std::vector<Point<3>> canonical, samples, queries;
    const double          delta = 1.0001 * sample_revolved(chain, 0.02, 1600, 5., canonical);
    for (const Point<3> &s : canonical)
      samples.push_back(frame.to_local(s));
    for (const Point<3> &q : random_points(Point<3>(-6, -6, -4), Point<3>(6, 6, 4), 60, 9))
      queries.push_back(frame.to_local(q));
    queries.push_back(frame.to_local(Point<3>(0., 0., 4.)));  // beyond a vertex / face
    std::vector<Point<2>> poly = chain_polygon(chain, 0.001); // closed along the axis
    expect_brute_force(
        rev,
        samples,
        delta,
        queries,
        [&](const Point<3> &x)
        {
          const Point<3> xi = frame.to_canonical(x);
          return in_polygon(poly, std::hypot(xi[0], xi[1]), xi[2]);
        },
        1e-6); // the polygon of the fillets is off the arcs by < 0.001^2 / 4
    // the vertex of the cone is an edge, the face through the axis is not
    const SurfaceProjection<3> v = rev.project(frame.to_local(Point<3>(0., 0., 4.)));
    EXPECT_FALSE(v.at_end);
    EXPECT_EQ(v.at_edge, !is_barrel);
    for (const Point<3> &q : random_points(Point<3>(-6, -6, -4), Point<3>(6, 6, 4), 30, 10))
      expect_curvatures_by_differences(rev, frame.to_local(q));
  }
  // a profile reaching r < 0 is refused
  EXPECT_THROW(RevolvedProfile(polyline_chain({Point<2>(-1., 1.), Point<2>(2., 1.)})),
               ausroll::EntryError);
}

// ============================================================================ extruded profile
TEST(Surfaces3D, ExtrudedCircleIsTheSharpCylinder)
{
  const double          R = 5., h = 2.;
  const FiniteCylinder  cyl(oblique_origin, oblique_axis, R, 2. * h, 0., oblique_reference);
  const ExtrudedProfile ext(
      circle_chain(Point<2>(), R), -h, h, true, oblique_origin, oblique_axis, oblique_reference);
  const Frame3D frame(oblique_origin, oblique_axis, oblique_reference);
  for (const Point<3> &q : random_points(Point<3>(-7, -7, -4), Point<3>(7, 7, 4), 400, 11))
  {
    const Point<3>             x = frame.to_local(q);
    const SurfaceProjection<3> a = cyl.project(x), b = ext.project(x);
    expect_frame(x, b);
    expect_same(a, b, 10., false, false);
    const bool mantle = !a.at_edge && std::abs(a.normal * oblique_axis) < 1e-12;
    if (mantle)
    {
      // extrusion (e3, t_circle) = -(cylinder (-e3, e_theta)): the circle runs clockwise
      EXPECT_LE((a.tangents[0] + b.tangents[0]).norm(), 1e-12);
      EXPECT_LE((a.tangents[1] + b.tangents[1]).norm(), 1e-12);
      EXPECT_NEAR(b.coordinates[0], q[2], 1e-12 * 10.);
    }
  }
}

TEST(Surfaces3D, ExtrudedGearAgainstBruteForce)
{
  // 20 teeth, m = 2 mm, 20 degrees: a spur-gear die of face width 4 with end caps
  const ausroll::geometry::InvoluteGear gear(20, 2., 20. * numbers::PI / 180.);
  const CurveChain                      chain = involute_gear_chain(gear);
  const double                          z0 = -2., z1 = 2.;
  const ExtrudedProfile ext(chain, z0, z1, true, oblique_origin, oblique_axis, oblique_reference);
  const Frame3D         frame(oblique_origin, oblique_axis, oblique_reference);
  // samples (canonical): the mantle (chain every ds, z every dz) and the caps (grid dx inside the
  // polygon of the chain); covering radius: mantle cells 0.5 hypot(ds, dz), cap cells dx / sqrt 2,
  // cap cells cut by the outline within dx sqrt 2 + ds / 2 of an outline sample
  const double          ds = 0.02, dz = 0.02, dx = 0.02;
  std::vector<Point<3>> samples;
  const auto            n_s = static_cast<unsigned int>(std::ceil(chain.total_length() / ds));
  const unsigned int    n_z = static_cast<unsigned int>(std::ceil((z1 - z0) / dz));
  for (unsigned int i = 0; i < n_s; ++i)
  {
    const Point<2> q = chain.point_at(chain.total_length() * i / n_s);
    for (unsigned int k = 0; k <= n_z; ++k)
      samples.push_back(frame.to_local(Point<3>(q[0], q[1], z0 + (z1 - z0) * k / n_z)));
  }
  // inside test: the outline within +-20 degrees (the queries and cap samples lie within +-17)
  const std::vector<Point<2>> poly = star_sector_polygon(chain, 0.004, 20. * numbers::PI / 180.);
  // the caps only near the queries' region (x > 17): the rest of the gear is far from them
  for (double x = 17.; x <= 22.5; x += dx)
    for (double y = -5.; y <= 5.; y += dx)
      if (in_polygon(poly, x, y))
        for (const double z : {z0, z1})
          samples.push_back(frame.to_local(Point<3>(x, y, z)));
  const double delta = 1.0001 * (dx * std::sqrt(2.) + 0.5 * chain.total_length() / n_s);
  // queries near the teeth at polar angles within +-9 degrees of the x axis (1.5 teeth), inside
  // and outside, below, within and above the face width
  std::vector<Point<3>> queries;
  for (const Point<3> &q : random_points(Point<3>(19., -2.5, -3.), Point<3>(22.5, 2.5, 3.), 60, 12))
    queries.push_back(frame.to_local(q));
  expect_brute_force(
      ext,
      samples,
      delta,
      queries,
      [&](const Point<3> &x)
      {
        const Point<3> xi = frame.to_canonical(x);
        return xi[2] >= z0 && xi[2] <= z1 && in_polygon(poly, xi[0], xi[1]);
      },
      // the polygon of the curved segments is off them by < 3e-5 (the worst:
      // the start of the involute on the base circle, radius of curvature 0)
      5e-5);
  for (const Point<3> &q : random_points(Point<3>(19., -2.5, -3.), Point<3>(22.5, 2.5, 3.), 30, 13))
    expect_curvatures_by_differences(ext, frame.to_local(q));
}

TEST(Surfaces3D, ExtrudedOpenEndsAndInfinite)
{
  // a flat strip y = 0 (material below) of width [0, 3] without caps: beyond z = 3 the points
  // wrap around the end line (at_end); the infinite extrusion is the 2D projection times z
  const CurveChain           flat = flat_chain(Point<2>(), Tensor<1, 2>({1., 0.}));
  const ExtrudedProfile      open(flat, 0., 3., false);
  const ExtrudedProfile      infinite(flat);
  const SurfaceProjection<3> e = open.project(Point<3>(1., 0.5, 4.));
  EXPECT_TRUE(e.at_end && e.at_edge);
  EXPECT_NEAR(e.gap, std::hypot(0.5, 1.), 1e-14);
  EXPECT_LE((e.point - Point<3>(1., 0., 3.)).norm(), 1e-14);
  EXPECT_NEAR(open.project(Point<3>(1., -0.5, 4.)).gap, -std::hypot(0.5, 1.), 1e-14);
  const SurfaceProjection<3> i = infinite.project(Point<3>(1., -0.5, 40.));
  EXPECT_NEAR(i.gap, -0.5, 1e-14);
  EXPECT_FALSE(i.at_end || i.at_edge);
  EXPECT_NEAR(i.coordinates[0], 40., 1e-14);
  EXPECT_NEAR(i.coordinates[1], 1., 1e-14);
  EXPECT_THROW(ExtrudedProfile(flat, 1., 1.), ausroll::EntryError);
  EXPECT_THROW(ExtrudedProfile(flat, 0., std::numeric_limits<double>::infinity(), true),
               ausroll::EntryError);
}

// ============================================================================ continuity
TEST(Surfaces3D, SignedGapIsOneLipschitzAroundEdges)
{
  // pairs of points 1e-3 apart near the rims, faces, axis and edges of the closed solids
  const FiniteCylinder  sharp(Point<3>(), vec(0., 0., 1.), 5., 4., 0.);
  const FiniteCylinder  round(Point<3>(), vec(0., 0., 1.), 5., 4., 1.);
  const Torus           torus(Point<3>(), vec(0., 0., 1.), 6., 2.);
  const ExtrudedProfile gear(
      involute_gear_chain(ausroll::geometry::InvoluteGear(20, 2., 20. * numbers::PI / 180.)),
      -2.,
      2.,
      true);
  const std::vector<const RigidSurface<3> *> solids{&sharp, &round, &torus, &gear};
  std::mt19937                               rng(14);
  std::normal_distribution<double>           gauss(0., 1.);
  for (const RigidSurface<3> *s : solids)
    for (const Point<3> &x :
         random_points(Point<3>(-0.5, 3.5, -2.6), Point<3>(0.5, 21.5, 2.6), 3000, 15))
    {
      const Tensor<1, 3> d = 1e-3 * vec(gauss(rng), gauss(rng), gauss(rng));
      const double       g0 = s->project(x).gap, g1 = s->project(x + d).gap;
      EXPECT_LE(std::abs(g1 - g0), d.norm() + 1e-12) << s->name() << " x = " << x;
    }
}

TEST(Surfaces3D, ProjectionIsContinuousAroundConvexEdges)
{
  // a path at distance 0.3 around the sharp rim of the cylinder (from the face to the mantle) and
  // around a cap edge of the gear: the projected point stays on the edge, the normal turns
  // smoothly: |dn| <= dangle (+ rounding), the edge flag on the fan only
  const FiniteCylinder sharp(Point<3>(), vec(0., 0., 1.), 5., 4., 0.);
  const unsigned int   n = 200;
  Tensor<1, 3>         n_prev;
  Point<3>             p_prev;
  for (unsigned int k = 0; k <= n; ++k)
  {
    const double               a = -0.2 + (0.5 * numbers::PI + 0.4) * k / n; // from the face side
    const Point<3>             x(5. + 0.3 * std::sin(a), 0., 2. + 0.3 * std::cos(a));
    const SurfaceProjection<3> p = sharp.project(x);
    expect_frame(x, p);
    EXPECT_NEAR(p.gap,
                a < 0. || a > 0.5 * numbers::PI ? 0.3 * std::cos(a < 0. ? a : a - 0.5 * numbers::PI)
                                                : 0.3,
                1e-12);
    if (k > 0)
    {
      EXPECT_LE((p.normal - n_prev).norm(), (0.5 * numbers::PI + 0.4) / n * 1.001);
      EXPECT_LE((p.point - p_prev).norm(), 0.3 * (0.5 * numbers::PI + 0.4) / n * 1.001);
    }
    n_prev = p.normal;
    p_prev = p.point;
  }
  // the rounded rim: curvature 1/r_e between, projected point moves with the path
  const FiniteCylinder round(Point<3>(), vec(0., 0., 1.), 5., 4., 1.);
  for (unsigned int k = 0; k <= n; ++k)
  {
    const double               a = 0.5 * numbers::PI * k / n;
    const Point<3>             x(4. + 1.3 * std::sin(a), 0., 1. + 1.3 * std::cos(a));
    const SurfaceProjection<3> p = round.project(x);
    EXPECT_NEAR(p.gap, 0.3, 1e-12);
    EXPECT_NEAR(p.coordinates[0], 4. + a, 1e-12);
    EXPECT_LE((p.normal - vec(std::sin(a), 0., std::cos(a))).norm(), 1e-12);
  }
}

// ============================================================================ cone
// Cone (apex a, unit axis e, half angle alpha): the distance against the nearest of a dense set of
// surface points (brute force, covering radius h), x = x_proj + g n, the gap sign against the
// independent inside test {z > 0, r < z tan(alpha)}, and closed forms: a point on the axis inside
// at depth z has g = -z sin(alpha); a point behind the apex projects onto the apex (g = |x - a|,
// at_edge); a point off the surface along the outward normal n = cos(alpha) e_r - sin(alpha) e
// of a surface point has exactly that point as projection.
TEST(Surfaces3D, ConeAgainstBruteForce)
{
  const Point<3>     apex(1., -2., 0.5);
  const Tensor<1, 3> e = vec(1., 1., 1.) / std::sqrt(3.);
  const double       alpha = numbers::PI / 6.;
  const Cone         cone(apex, vec(1., 1., 1.), alpha, vec(1., 0., 0.));
  EXPECT_EQ(cone.name(), "cone");

  // an orthonormal pair normal to the axis for the samples (any pair: the surface is round)
  const Tensor<1, 3> e1 = (vec(1., 0., 0.) - (vec(1., 0., 0.) * e) * e)
                          / (vec(1., 0., 0.) - (vec(1., 0., 0.) * e) * e).norm();
  const Tensor<1, 3>    e2 = cross_product_3d(e, e1);
  const double          h = 0.01;
  std::vector<Point<3>> samples;
  for (double rho = 0.; rho <= 6.; rho += h)
  {
    const double       r = rho * std::sin(alpha), z = rho * std::cos(alpha);
    const unsigned int n = std::max(8u, static_cast<unsigned int>(2. * numbers::PI * r / h) + 1);
    for (unsigned int k = 0; k < n; ++k)
    {
      const double t = 2. * numbers::PI * k / n;
      samples.push_back(apex + z * e + r * (std::cos(t) * e1 + std::sin(t) * e2));
    }
  }
  const auto inside = [&](const Point<3> &x)
  {
    const Tensor<1, 3> d = x - apex;
    const double       z = d * e, r = (d - z * e).norm();
    return z > 0. && r < z * std::tan(alpha);
  };
  expect_brute_force(cone,
                     samples,
                     h,
                     random_points(apex + vec(-2., -2., -2.), apex + vec(2., 2., 2.), 300, 17),
                     inside);

  // closed forms
  for (const double z : {0.3, 1., 2.5})
  {
    const SurfaceProjection<3> p = cone.project(apex + z * e);
    expect_frame(apex + z * e, p);
    EXPECT_NEAR(p.gap, -z * std::sin(alpha), 1e-12);
  }
  const Point<3>             behind = apex - 0.7 * e + 0.1 * e1;
  const SurfaceProjection<3> q = cone.project(behind);
  expect_frame(behind, q);
  EXPECT_TRUE(q.at_edge);
  EXPECT_NEAR(q.gap, (behind - apex).norm(), 1e-12);
  EXPECT_LE((q.point - apex).norm(), 1e-12);
  for (const double rho : {0.5, 2.})
    for (const double t : {0., 1., 4.})
      for (const double g : {-0.2, 0.1, 0.8})
      {
        const Tensor<1, 3>         e_r = std::cos(t) * e1 + std::sin(t) * e2;
        const Point<3>             on = apex + rho * (std::cos(alpha) * e + std::sin(alpha) * e_r);
        const Tensor<1, 3>         n = std::cos(alpha) * e_r - std::sin(alpha) * e;
        const SurfaceProjection<3> p = cone.project(on + g * n);
        EXPECT_LE((p.point - on).norm(), 1e-12);
        EXPECT_LE((p.normal - n).norm(), 1e-12);
        EXPECT_NEAR(p.gap, g, 1e-12);
        EXPECT_FALSE(p.at_edge);
        EXPECT_NEAR(p.curvatures[0], 0., 1e-14);
        EXPECT_NEAR(p.curvatures[1], std::cos(alpha) / (rho * std::sin(alpha)), 1e-12);
      }
  // the search distance
  EXPECT_FALSE(cone.project(apex + 3. * e1, 0.5).valid);
  // a half angle outside (0, 90) degrees
  EXPECT_THROW(Cone(apex, e, numbers::PI / 2.), ausroll::EntryError);
}

// ============================================================================ parameters
namespace
{
  /**
   * The die-shape entries of @p text (all shape subsections declared inside `Contact/Die 0`, as
   * ContactParameters does); create() parses the named 3D shape's subsection through the registry
   * and makes the surface.
   */
  struct ParsedShapes
  {
    std::string text;

    std::unique_ptr<const RigidSurface<3>> create(const std::string &shape) const
    {
      dealii::ParameterHandler prm;
      prm.enter_subsection("Contact");
      prm.enter_subsection("Die 0");
      declare_shape_parameters(prm);
      prm.leave_subsection();
      prm.leave_subsection();
      prm.parse_input_from_string(text);
      prm.enter_subsection("Contact");
      prm.enter_subsection("Die 0");
      const auto &registry = ShapeRegistry<3>::instance();
      const auto  parameters = registry.parse(shape, prm, "Contact/Die 0/", "/tmp/", "Shape");
      prm.leave_subsection();
      prm.leave_subsection();
      return parameters->create(registry.path(shape, "Contact/Die 0/"));
    }
  };

  ParsedShapes parse(const std::string &text)
  {
    return {text};
  }

  /** The message of the InputError thrown by @p f ("" if none). */
  std::string error_of(const std::function<void()> &f)
  {
    try
    {
      f();
    }
    catch (const ausroll::InputError &e)
    {
      return e.what();
    }
    return "";
  }
} // namespace

TEST(Surfaces3D, ParametersBuildEveryShape)
{
  const ParsedShapes p = parse(R"(
subsection Contact
  subsection Die 0
    subsection Cylinder
      set Center = 0, 0, 120
      set Axis = 1, 0, 0
      set Radius = 116.55
      set Width = 30
      set Edge radius = 2
    end
    subsection Torus
      set Major radius = 116.6
      set Minor radius = 2.03
    end
    subsection Revolved profile
      subsection Profile
        set Type = arc line
        subsection Arc line
          set Points = 0, 2; 4, 2; 5, 0; 4, -2; 0, -2
          set Fillet radii = 0.5
        end
      end
    end
    subsection Extruded profile
      set Extent = finite with caps
      set Start z = -2
      set End z = 2
      subsection Profile
        set Type = involute gear
        subsection Involute gear
          set Number of teeth = 20
          set Diametral pitch = 0
          set Module = 2
        end
      end
    end
  end
end
)");
  for (const std::string shape :
       {"plane", "cylinder", "torus", "revolved profile", "extruded profile", "cone"})
  {
    const auto s = p.create(shape);
    ASSERT_TRUE(s);
    EXPECT_EQ(s->name(), shape);
  }
  // the cylinder lies as given: axis x, centre (0, 0, 120), radius 116.55
  const auto                 cyl = p.create("cylinder");
  const SurfaceProjection<3> q = cyl->project(Point<3>(5., 0., 0.));
  EXPECT_NEAR(q.gap, 120. - 116.55, 1e-12);
  EXPECT_LE((q.normal - vec(0., 0., -1.)).norm(), 1e-14);
  const auto torus = p.create("torus");
  EXPECT_NEAR(torus->project(Point<3>(120., 0., 0.)).gap, 120. - 116.6 - 2.03, 1e-12);
}

TEST(Surfaces3D, ParameterErrorsNameTheFullPath)
{
  auto message = [](const std::string &text, const std::string &shape)
  { return error_of([&]() { parse(text).create(shape); }); };
  EXPECT_EQ(
      message("subsection Contact\nsubsection Die 0\nsubsection Cylinder\nset Edge radius = 0.75\n"
              "end\nend\nend\n",
              "cylinder"),
      "Contact/Die 0/Cylinder/Edge radius: must lie in [0, min(Radius, Width / 2)]");
  EXPECT_EQ(message("subsection Contact\nsubsection Die 0\nsubsection Torus\nset Minor radius = 3\n"
                    "end\nend\nend\n",
                    "torus"),
            "Contact/Die 0/Torus/Minor radius: must be positive and smaller than Major radius");
  EXPECT_EQ(message("subsection Contact\nsubsection Die 0\nsubsection Plane\nset Normal = 0, 0, 0\n"
                    "end\nend\nend\n",
                    "plane"),
            "Contact/Die 0/Plane/Normal: must be a nonzero vector");
  EXPECT_NE(message("subsection Contact\nsubsection Die 0\nsubsection Cylinder\nset Axis = 1, 0\n"
                    "end\nend\nend\n",
                    "cylinder")
                .find("Contact/Die 0/Cylinder/Axis"),
            std::string::npos);
  EXPECT_EQ(
      message("subsection Contact\nsubsection Die 0\nsubsection Revolved profile\nsubsection "
              "Profile\nsubsection Polyline\nset Points = -1, 1; 2, 1\nend\nend\nend\nend\nend\n",
              "revolved profile")
          .rfind("Contact/Die 0/Revolved profile/Profile/Points: the profile must lie", 0),
      0u);
  EXPECT_EQ(message("subsection Contact\nsubsection Die 0\nsubsection Revolved profile\nsubsection "
                    "Profile\nsubsection Polyline\nset Points = 1, 1\nend\nend\nend\nend\nend\n",
                    "revolved profile"),
            "Contact/Die 0/Revolved profile/Profile/Polyline/Points: needs at least two points");
  EXPECT_EQ(
      message("subsection Contact\nsubsection Die 0\nsubsection Extruded profile\nset Extent = "
              "finite\nset Start z = 2\nset End z = 1\nend\nend\nend\n",
              "extruded profile"),
      "Contact/Die 0/Extruded profile/End z: must be larger than Start z");
  EXPECT_NE(message("subsection Contact\nsubsection Die 0\nsubsection Extruded profile\nsubsection "
                    "Profile\nset Type = polyline\nsubsection Polyline\nset Points file = "
                    "missing.txt\nend\nend\nend\n"
                    "end\nend\n",
                    "extruded profile")
                .find("Contact/Die 0/Extruded profile/Profile/Polyline/Points file: "),
            std::string::npos);
  EXPECT_NE(
      message(
          "subsection Contact\nsubsection Die 0\nsubsection Extruded profile\nsubsection "
          "Profile\nset Type = involute gear\nsubsection Involute gear\nset Number of teeth = 20\n"
          "set Tip radius = 50\nend\nend\nend\nend\nend\n",
          "extruded profile")
          .find("Contact/Die 0/Extruded profile/Profile/Involute gear/Tip radius: "),
      std::string::npos);
}

// point_at() inverts the projection's surface coordinates (the die output samples the surfaces
// through it): point_at(project(x).coordinates) = project(x).point to 1e-12 of the size, for
// every shape (the extruded profile without caps: cap coordinates are not unique), also after
// shifting a periodic coordinate by its period; and a few points of the cylinder's meridian
// profile at known s (upper face, rim, mantle, lower rim, lower face).
TEST(Surfaces3D, PointAtInvertsTheProjection)
{
  const ausroll::geometry::InvoluteGear gear(20, 2., 20. * numbers::PI / 180.);
  const FiniteCylinder  cylinder(oblique_origin, oblique_axis, 5., 3., 0.5, oblique_reference);
  const FiniteCylinder  sharp(oblique_origin, oblique_axis, 5., 3., 0., oblique_reference);
  const Torus           torus(oblique_origin, oblique_axis, 5., 1.5, oblique_reference);
  const Plane           plane(oblique_origin, oblique_axis, oblique_reference, 3., 2.);
  const RevolvedProfile barrel(arc_line_chain({Point<2>(0., 2.),
                                               Point<2>(4., 2.),
                                               Point<2>(5., 0.),
                                               Point<2>(4., -2.),
                                               Point<2>(0., -2.)},
                                              {0.5}),
                               oblique_origin,
                               oblique_axis,
                               oblique_reference);
  const ExtrudedProfile extruded(
      involute_gear_chain(gear), -2., 2., false, oblique_origin, oblique_axis, oblique_reference);
  const std::vector<const RigidSurface<3> *> shapes{
      &cylinder, &sharp, &torus, &plane, &barrel, &extruded};
  for (const RigidSurface<3> *shape : shapes)
    for (const Point<3> &x : random_points(Point<3>(-25, -25, -25), Point<3>(25, 25, 25), 200, 5))
    {
      const SurfaceProjection<3> p = shape->project(x);
      ASSERT_TRUE(p.valid);
      EXPECT_LE((shape->point_at(p.coordinates) - p.point).norm(), 1e-12 * 25.)
          << shape->name() << ": x = " << x;
      std::array<double, 2> shifted = p.coordinates;
      for (unsigned int a = 0; a < 2; ++a)
        shifted[a] += shape->coordinate_periods()[a];
      EXPECT_LE((shape->point_at(shifted) - p.point).norm(), 1e-11 * 25.) << shape->name();
    }
  // the cylinder R = 5, w = 3, r_e = 0.5 in its canonical frame: a = 4.5, b = 1
  const Frame3D frame(oblique_origin, oblique_axis, oblique_reference);
  const double  a = 4.5, b = 1., quarter = 0.25 * numbers::PI;
  const std::vector<std::pair<double, Point<3>>> known{
      {2., Point<3>(2., 0., 1.5)},
      {a + 0.5 * quarter,
       Point<3>(
           a + 0.5 * std::sin(0.25 * numbers::PI), 0., b + 0.5 * std::cos(0.25 * numbers::PI))},
      {a + quarter + 0.5, Point<3>(5., 0., 0.5)},
      {a + quarter + 2. * b + quarter, Point<3>(a, 0., -1.5)},
      {a + quarter + 2. * b + quarter + a, Point<3>(0., 0., -1.5)}};
  for (const auto &[s, canonical] : known)
    EXPECT_LE((cylinder.point_at({{s, 0.}}) - frame.to_local(canonical)).norm(), 1e-12) << s;
}

TEST(Surfaces3D, ConeParameters)
{
  // every shape file's registration reached this executable (ausroll_core is an OBJECT library)
  EXPECT_EQ(ShapeRegistry<2>::instance().selection(),
            "arc line|circle|ellipse|flat|involute gear|polyline");
  EXPECT_EQ(ShapeRegistry<3>::instance().selection(),
            "cone|cylinder|extruded profile|plane|revolved profile|torus");

  const ParsedShapes p = parse("subsection Contact\nsubsection Die 0\nsubsection Cone\n"
                               "set Apex = 0, 0, 2\nset Axis = 0, 0, 1\nset Half angle = 60\n"
                               "end\nend\nend\n");
  const auto         cone = p.create("cone");
  EXPECT_EQ(cone->name(), "cone");
  // a point on the axis inside at depth 1: g = -sin(60 degrees)
  EXPECT_NEAR(cone->project(Point<3>(0., 0., 3.)).gap, -std::sin(numbers::PI / 3.), 1e-12);
  EXPECT_EQ(error_of(
                [&]()
                {
                  parse("subsection Contact\nsubsection Die 0\nsubsection Cone\nset Axis = 0, 0, "
                        "0\nend\nend\nend\n")
                      .create("cone");
                }),
            "Contact/Die 0/Cone/Axis: must be a nonzero vector");
}
