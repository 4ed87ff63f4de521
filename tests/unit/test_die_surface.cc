/**
 * @file test_die_surface.cc
 * Unit tests of geometry::CurveChain and the chains of the 2D die shapes: projections (gap, normal,
 * tangent, s) on flats, circles, polyline corners (convex and concave), line-arc composites,
 * involute flanks and gear dies; point_at / arc-length round trips; points files; the search band.
 */
#include <ausroll/contact/surfaces/arc_line.h>
#include <ausroll/contact/surfaces/circle.h>
#include <ausroll/contact/surfaces/flat.h>
#include <ausroll/contact/surfaces/involute_gear.h>
#include <ausroll/contact/surfaces/polyline.h>
#include <ausroll/core/exceptions.h>
#include <ausroll/geometry/curve_chain.h>
#include <ausroll/geometry/involute_gear.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>

#include <unistd.h>

using ausroll::contact::surfaces::arc_line_chain;
using ausroll::contact::surfaces::circle_chain;
using ausroll::contact::surfaces::flat_chain;
using ausroll::contact::surfaces::involute_flank_chain;
using ausroll::contact::surfaces::involute_gear_chain;
using ausroll::contact::surfaces::polyline_chain;
using ausroll::contact::surfaces::polyline_chain_from_file;
using ausroll::contact::surfaces::read_points_file;
using ausroll::geometry::CurveChain;
using ausroll::geometry::CurveSegment;
using Projection = ausroll::geometry::SurfaceProjection<2>;
using dealii::Point;
using dealii::Tensor;

namespace
{
  Tensor<1, 2> vec(const double x, const double y)
  {
    Tensor<1, 2> v;
    v[0] = x;
    v[1] = y;
    return v;
  }

  /** Check a projection against hand-computed values. */
  void expect_projection(const Projection   &p,
                         const Point<2>     &point,
                         const double        gap,
                         const Tensor<1, 2> &normal,
                         const double        s,
                         const double        tol = 1e-12)
  {
    ASSERT_TRUE(p.valid);
    EXPECT_NEAR(p.point[0], point[0], tol);
    EXPECT_NEAR(p.point[1], point[1], tol);
    EXPECT_NEAR(p.gap, gap, tol);
    EXPECT_NEAR(p.distance, std::abs(gap), tol);
    EXPECT_NEAR(p.normal[0], normal[0], tol);
    EXPECT_NEAR(p.normal[1], normal[1], tol);
    EXPECT_NEAR(p.coordinates[0], s, tol);
    // Tangent = normal rotated by -90 degrees.
    EXPECT_NEAR(p.tangents[0][0], normal[1], tol);
    EXPECT_NEAR(p.tangents[0][1], -normal[0], tol);
  }

  /** x = x_proj + g n must hold for every projection. */
  void expect_consistent(const Point<2> &x, const Projection &p, const double tol = 1e-12)
  {
    ASSERT_TRUE(p.valid);
    const Point<2> back = p.point + p.gap * p.normal;
    EXPECT_NEAR(back[0], x[0], tol);
    EXPECT_NEAR(back[1], x[1], tol);
    EXPECT_NEAR(p.normal.norm(), 1.0, 1e-14);
  }

  /** Unique temporary file name for this test process. */
  std::string temporary_file(const std::string &name)
  {
    return (std::filesystem::temp_directory_path()
            / ("ausroll_test_die_surface_" + std::to_string(::getpid()) + "_" + name))
        .string();
  }

  /** Dense sampling of a die: brute-force reference for distances. */
  double
  brute_force_distance(const CurveChain &die, const Point<2> &x, const unsigned int n_per_segment)
  {
    double best = std::numeric_limits<double>::infinity();
    for (unsigned int i = 0; i < die.n_segments(); ++i)
    {
      const CurveSegment &seg = die.segment(i);
      for (unsigned int j = 0; j <= n_per_segment; ++j)
        best = std::min(best,
                        x.distance(seg.point(seg.u_begin() + seg.length() * j / n_per_segment)));
    }
    return best;
  }
} // namespace

TEST(CurveChain, InfiniteFlat)
{
  const CurveChain die = flat_chain(Point<2>(0.0, 1.0), vec(2.0, 0.0));
  EXPECT_TRUE(std::isinf(die.total_length()));
  // Workpiece on the left of the direction: n = +y.
  expect_projection(die.project(Point<2>(3.0, 3.0)), Point<2>(3.0, 1.0), 2.0, vec(0, 1), 3.0);
  expect_projection(die.project(Point<2>(-1.0, 0.5)), Point<2>(-1.0, 1.0), -0.5, vec(0, 1), -1.0);
  EXPECT_FALSE(die.project(Point<2>(-1.0, 0.5)).at_end);
  EXPECT_EQ(die.project(Point<2>(1e6, 2.0)).curvatures[0], 0.0);
  // Upper die: direction -x, normal -y.
  const CurveChain upper = flat_chain(Point<2>(0.0, 5.0), vec(-1.0, 0.0));
  expect_projection(upper.project(Point<2>(2.0, 4.0)), Point<2>(2.0, 5.0), 1.0, vec(0, -1), -2.0);
}

TEST(CurveChain, FiniteFlatEnds)
{
  const CurveChain die = flat_chain(Point<2>(1.0, 1.0), vec(1.0, 0.0), 2.0);
  EXPECT_NEAR(die.total_length(), 4.0, 1e-15);
  expect_projection(die.project(Point<2>(0.0, 0.0)), Point<2>(0.0, 1.0), -1.0, vec(0, 1), 1.0);
  // Beyond the end, outside: wraps around the end point.
  const Projection p = die.project(Point<2>(5.0, 2.0));
  expect_projection(p, Point<2>(3.0, 1.0), std::sqrt(5.0), vec(2, 1) / std::sqrt(5.0), 4.0);
  EXPECT_TRUE(p.at_end);
  // Beyond the end, behind the die: penetration.
  const Projection q = die.project(Point<2>(4.0, 0.5));
  expect_projection(q, Point<2>(3.0, 1.0), -std::sqrt(1.25), -vec(1, -0.5) / std::sqrt(1.25), 4.0);
  EXPECT_TRUE(q.at_end);
  expect_consistent(Point<2>(4.0, 0.5), q);
}

TEST(CurveChain, CircleDieRoll)
{
  const Point<2>   c(1.0, 2.0);
  const CurveChain roll = circle_chain(c, 3.0);
  EXPECT_NEAR(roll.total_length(), 6.0 * M_PI, 1e-14);
  // Outside on +x: s = 0; normal outward, tangent clockwise.
  const Projection a = roll.project(Point<2>(6.0, 2.0));
  expect_projection(a, Point<2>(4.0, 2.0), 2.0, vec(1, 0), 0.0);
  EXPECT_NEAR(a.curvatures[0], 1.0 / 3.0, 1e-15);
  // Inside, above the centre: clockwise from angle 0 to pi/2 is 3/4 of the circle.
  expect_projection(
      roll.project(Point<2>(1.0, 3.0)), Point<2>(1.0, 5.0), -2.0, vec(0, 1), 4.5 * M_PI);
  // Far away.
  const Projection f = roll.project(Point<2>(1.0, -1e4));
  expect_projection(f, Point<2>(1.0, -1.0), 1e4 - 1.0, vec(0, -1), 1.5 * M_PI, 1e-9);
  EXPECT_FALSE(f.at_edge || f.at_end);
}

TEST(CurveChain, CircleHoleConcave)
{
  const CurveChain hole = circle_chain(Point<2>(0.0, 0.0), 3.0, false);
  // Inside the hole (the open space): normal towards the centre, positive gap.
  const Projection a = hole.project(Point<2>(1.0, 0.0));
  expect_projection(a, Point<2>(3.0, 0.0), 2.0, vec(-1, 0), 0.0);
  EXPECT_NEAR(a.curvatures[0], -1.0 / 3.0, 1e-15);
  // Outside the circle = in the material.
  expect_projection(
      hole.project(Point<2>(0.0, 5.0)), Point<2>(0.0, 3.0), -2.0, vec(0, -1), 1.5 * M_PI);
}

TEST(CurveChain, PolylineConvexCorner)
{
  // Top and right side of a block (material below-left): right turn at (2, 0) = convex.
  const CurveChain die
      = polyline_chain({Point<2>(0.0, 0.0), Point<2>(2.0, 0.0), Point<2>(2.0, -2.0)});
  EXPECT_NEAR(die.total_length(), 4.0, 1e-15);
  const Projection corner = die.project(Point<2>(3.0, 1.0));
  expect_projection(corner, Point<2>(2.0, 0.0), std::sqrt(2.0), vec(1, 1) / std::sqrt(2.0), 2.0);
  EXPECT_TRUE(corner.at_edge);
  EXPECT_FALSE(corner.at_end);
  // Exactly on the corner: zero gap, bisector normal.
  expect_projection(
      die.project(Point<2>(2.0, 0.0)), Point<2>(2.0, 0.0), 0.0, vec(1, 1) / std::sqrt(2.0), 2.0);
  expect_projection(die.project(Point<2>(1.0, 0.5)), Point<2>(1.0, 0.0), 0.5, vec(0, 1), 1.0);
  expect_projection(die.project(Point<2>(2.5, -1.0)), Point<2>(2.0, -1.0), 0.5, vec(1, 0), 3.0);
  // Inside near the corner: the nearer side wins.
  const Projection in = die.project(Point<2>(1.8, -0.1));
  expect_projection(in, Point<2>(1.8, 0.0), -0.1, vec(0, 1), 1.8);
  EXPECT_EQ(die.segment_index(in.coordinates[0]), 0u);
  const Projection in2 = die.project(Point<2>(1.9, -0.5));
  expect_projection(in2, Point<2>(2.0, -0.5), -0.1, vec(1, 0), 2.5);
  EXPECT_EQ(die.segment_index(in2.coordinates[0]), 1u);
}

TEST(CurveChain, PolylineConcaveCorner)
{
  // Floor then wall (material below and right): left turn at (2, 0) = concave.
  const CurveChain die
      = polyline_chain({Point<2>(0.0, 0.0), Point<2>(2.0, 0.0), Point<2>(2.0, 2.0)});
  expect_projection(die.project(Point<2>(1.5, 0.2)), Point<2>(1.5, 0.0), 0.2, vec(0, 1), 1.5);
  expect_projection(die.project(Point<2>(1.8, 1.0)), Point<2>(2.0, 1.0), 0.2, vec(-1, 0), 3.0);
  // On the bisector: equal distances, the first segment is taken (no double counting).
  const Projection b = die.project(Point<2>(1.5, 0.5));
  expect_projection(b, Point<2>(1.5, 0.0), 0.5, vec(0, 1), 1.5);
  EXPECT_EQ(die.segment_index(b.coordinates[0]), 0u);
  // Penetration into the wall near the corner: the nearer segment wins.
  const Projection w = die.project(Point<2>(2.05, 0.3));
  expect_projection(w, Point<2>(2.0, 0.3), -0.05, vec(-1, 0), 2.3);
  EXPECT_EQ(die.segment_index(w.coordinates[0]), 1u);
  // Deep in the material wedge behind the corner: the corner itself, penetration.
  const Point<2>   x(2.3, -0.2);
  const Projection c = die.project(x);
  const double     d = std::sqrt(0.13);
  expect_projection(c, Point<2>(2.0, 0.0), -d, -vec(0.3, -0.2) / d, 2.0);
  EXPECT_TRUE(c.at_edge);
  expect_consistent(x, c);
}

TEST(CurveChain, ClosedPolylineAndReversal)
{
  // Unit square travelled clockwise: material inside.
  const std::vector<Point<2>> square
      = {Point<2>(0, 0), Point<2>(0, 1), Point<2>(1, 1), Point<2>(1, 0)};
  const CurveChain die = polyline_chain(square, true);
  EXPECT_TRUE(die.is_closed());
  EXPECT_NEAR(die.total_length(), 4.0, 1e-15);
  EXPECT_NEAR(die.project(Point<2>(0.5, 0.6)).gap, -0.4, 1e-15);
  EXPECT_NEAR(die.project(Point<2>(-1.0, -1.0)).gap, std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(die.project(Point<2>(-1.0, -1.0)).coordinates[0],
              0.0,
              1e-15); // corner joining last and first
  // Reversed: the material is outside, the gaps change sign.
  const CurveChain rev = die.reversed();
  EXPECT_NEAR(rev.project(Point<2>(0.5, 0.6)).gap, 0.4, 1e-15);
  EXPECT_NEAR(rev.project(Point<2>(-1.0, -1.0)).gap, -std::sqrt(2.0), 1e-15);
  // point_at wraps around for a closed chain.
  const Point<2> p = die.point_at(4.0 + 1.5);
  EXPECT_NEAR(p[0], 0.5, 1e-15);
  EXPECT_NEAR(p[1], 1.0, 1e-15);
}

TEST(CurveChain, PolylineExtendedEnds)
{
  const CurveChain die
      = polyline_chain({Point<2>(0.0, 0.0), Point<2>(1.0, 0.0), Point<2>(2.0, 1.0)}, false, true);
  EXPECT_TRUE(std::isinf(die.total_length()));
  const Projection a = die.project(Point<2>(-5.0, 1.0));
  expect_projection(a, Point<2>(-5.0, 0.0), 1.0, vec(0, 1), -5.0);
  EXPECT_FALSE(a.at_end);
  // Along the last side (direction (1, 1)/sqrt 2, normal (-1, 1)/sqrt 2), far beyond its end.
  const Projection b = die.project(Point<2>(9.5, 10.5));
  expect_projection(b,
                    Point<2>(10.5, 9.5),
                    std::sqrt(2.0),
                    vec(-1, 1) / std::sqrt(2.0),
                    1.0 + 9.5 * std::sqrt(2.0),
                    1e-12);
  EXPECT_FALSE(b.at_end);
}

TEST(CurveChain, PunchLineArcComposite)
{
  // Punch pressing down: right wall, bottom, left wall, both corners rounded with r = 1.
  const CurveChain punch
      = arc_line_chain({Point<2>(5, 5), Point<2>(5, 0), Point<2>(-5, 0), Point<2>(-5, 5)}, {1.0});
  ASSERT_EQ(punch.n_segments(), 5u);
  EXPECT_EQ(punch.segment(1).type(), CurveSegment::Type::arc);
  EXPECT_NEAR(punch.total_length(), 16.0 + M_PI, 1e-13);
  // Outside the fillet at 45 degrees.
  const Tensor<1, 2> e = vec(std::cos(-M_PI / 4), std::sin(-M_PI / 4));
  const Projection   f = punch.project(Point<2>(4.0, 1.0) + 2.0 * e);
  expect_projection(f, Point<2>(4.0, 1.0) + e, 1.0, e, 4.0 + M_PI / 4.0);
  EXPECT_NEAR(f.curvatures[0], 1.0, 1e-14);
  EXPECT_EQ(punch.segment_index(f.coordinates[0]), 1u);
  // Penetration under the bottom.
  expect_projection(
      punch.project(Point<2>(0.0, 0.3)), Point<2>(0.0, 0.0), -0.3, vec(0, -1), 8.0 + M_PI / 2.0);
  // Left wall.
  expect_projection(
      punch.project(Point<2>(-6.0, 3.0)), Point<2>(-5.0, 3.0), 1.0, vec(-1, 0), 14.0 + M_PI, 1e-12);
}

TEST(CurveChain, ConcaveFilletComposite)
{
  // Floor then wall with a concave fillet r = 1 (centre (-1, 1)).
  const CurveChain   die = arc_line_chain({Point<2>(-5, 0), Point<2>(0, 0), Point<2>(0, 5)}, {1.0});
  const Tensor<1, 2> e = vec(std::cos(-M_PI / 4), std::sin(-M_PI / 4));
  const Projection   p = die.project(Point<2>(-1.0, 1.0) + 0.5 * e);
  expect_projection(p, Point<2>(-1.0, 1.0) + e, 0.5, -e, 4.0 + M_PI / 4.0);
  EXPECT_NEAR(p.curvatures[0], -1.0, 1e-14);
  // Behind the fillet, in the material.
  const Projection q = die.project(Point<2>(-1.0, 1.0) + 1.2 * e);
  expect_projection(q, Point<2>(-1.0, 1.0) + e, -0.2, -e, 4.0 + M_PI / 4.0);
  EXPECT_THROW(arc_line_chain({Point<2>(-1, 0), Point<2>(0, 0), Point<2>(0, 5)}, {2.0}),
               ausroll::InputError);
}

TEST(CurveChain, ArcLengthRoundTrip)
{
  const CurveChain punch
      = arc_line_chain({Point<2>(5, 5), Point<2>(5, 0), Point<2>(-5, 0), Point<2>(-5, 5)}, {1.0});
  const CurveChain roll = circle_chain(Point<2>(0.5, -0.5), 2.0);
  for (const CurveChain *die : {&punch, &roll})
    for (unsigned int k = 0; k <= 40; ++k)
    {
      const double   s = die->total_length() * (k + 0.37) / 41.0;
      const Point<2> p = die->point_at(s);
      // On the surface and offset along the normal (outside and inside).
      for (const double g : {0.0, 0.25, -0.25})
      {
        const Point<2>   x = p + g * die->normal_at(s);
        const Projection pr = die->project(x);
        EXPECT_NEAR(pr.coordinates[0], s, 1e-12) << "s = " << s << ", g = " << g;
        EXPECT_NEAR(pr.gap, g, 1e-12);
        expect_consistent(x, pr);
      }
      // Arc length between nearby points equals the chord for small steps.
      const double ds = 1e-4;
      EXPECT_NEAR(die->point_at(s + ds).distance(die->point_at(s)), ds, 1e-9);
    }
  // Clamping of an open chain.
  EXPECT_NEAR(punch.point_at(-3.0).distance(Point<2>(5, 5)), 0.0, 1e-15);
  EXPECT_NEAR(punch.point_at(1e3).distance(Point<2>(-5, 5)), 0.0, 1e-15);
}

TEST(CurveChain, PointsFile)
{
  const std::string name = temporary_file("points.txt");
  {
    std::ofstream out(name);
    out << "# lower die contour, mm\n"
        << "0 0   # start\n"
        << "\n"
        << "  2.5 0.0\n"
        << "2.5 -1e0\n";
  }
  const std::vector<Point<2>> points = read_points_file(name);
  ASSERT_EQ(points.size(), 3u);
  EXPECT_EQ(points[1], Point<2>(2.5, 0.0));
  EXPECT_EQ(points[2], Point<2>(2.5, -1.0));
  const CurveChain die = polyline_chain_from_file(name);
  EXPECT_NEAR(die.total_length(), 3.5, 1e-15);
  EXPECT_NEAR(die.project(Point<2>(1.0, 0.5)).gap, 0.5, 1e-15);
  std::remove(name.c_str());

  // Missing file: std::runtime_error naming the file.
  const std::string missing = temporary_file("does_not_exist.txt");
  try
  {
    polyline_chain_from_file(missing);
    FAIL() << "no exception for a missing file";
  }
  catch (const std::runtime_error &e)
  {
    EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
  }

  // One point only, and a malformed line.
  const std::string one = temporary_file("one.txt");
  std::ofstream(one) << "1 2\n# nothing else\n";
  try
  {
    polyline_chain_from_file(one);
    FAIL() << "no exception for a single point";
  }
  catch (const std::runtime_error &e)
  {
    EXPECT_NE(std::string(e.what()).find(one), std::string::npos) << e.what();
  }
  std::ofstream(one) << "1 2\n3 x\n";
  EXPECT_THROW(read_points_file(one), std::runtime_error);
  std::ofstream(one) << "1 2\n3 4 5\n";
  EXPECT_THROW(read_points_file(one), std::runtime_error);
  std::remove(one.c_str());
}

TEST(CurveChain, SearchBand)
{
  const CurveChain die
      = polyline_chain({Point<2>(0.0, 0.0), Point<2>(2.0, 0.0), Point<2>(2.0, -2.0)});
  EXPECT_FALSE(die.project(Point<2>(1.0, 5.0), 1.0).valid);
  EXPECT_FALSE(die.project(Point<2>(100.0, 100.0), 1.0).valid);
  const Projection near = die.project(Point<2>(1.0, 0.5), 1.0);
  expect_projection(near, Point<2>(1.0, 0.0), 0.5, vec(0, 1), 1.0);
  // The band must not change the result for points within it.
  const Projection corner = die.project(Point<2>(2.3, 0.4), 0.6);
  expect_projection(corner, Point<2>(2.0, 0.0), 0.5, vec(0.3, 0.4) / 0.5, 2.0);
}

TEST(CurveChain, InvoluteFlankMatchesBruteForce)
{
  // Positive flank of a tooth with axis +x: base radius 20, beta_0 = 0.1, roll 0 ... 0.6.
  const double        rb = 20.0, beta0 = 0.1;
  const CurveChain    flank = involute_flank_chain(Point<2>(), rb, beta0, -1, 0.0, 0.6);
  const CurveSegment &seg = flank.segment(0);
  EXPECT_NEAR(flank.total_length(), 0.5 * rb * 0.36, 1e-13);
  // Start on the base circle at polar angle beta_0; tangent radial there.
  EXPECT_NEAR(
      seg.start_point().distance(Point<2>(rb * std::cos(beta0), rb * std::sin(beta0))), 0.0, 1e-13);
  // Flank points at roll u have radius r_b sqrt(1 + u^2) and polar angle beta_0 - (u - atan u).
  const Point<2> p = flank.point_at(0.5 * rb * 0.25); // u = 0.5
  EXPECT_NEAR(p.norm(), rb * std::sqrt(1.25), 1e-12);
  EXPECT_NEAR(std::atan2(p[1], p[0]), beta0 - (0.5 - std::atan(0.5)), 1e-13);
  EXPECT_NEAR(seg.curvature(0.5 * rb * 0.25), 1.0 / (rb * 0.5), 1e-13); // convex tooth flank
  // Bounding box holds the curve.
  for (unsigned int j = 0; j <= 100; ++j)
  {
    const Point<2> q = seg.point(seg.length() * j / 100.0);
    EXPECT_EQ(seg.distance_to_bounding_box(q), 0.0);
  }
  // Random points around the flank: exact projection vs dense sampling.
  std::mt19937                           rng(42);
  std::uniform_real_distribution<double> ux(15.0, 26.0), uy(-4.0, 8.0);
  for (unsigned int k = 0; k < 300; ++k)
  {
    const Point<2>   x(ux(rng), uy(rng));
    const Projection pr = flank.project(x);
    const double     d = brute_force_distance(flank, x, 20000);
    EXPECT_NEAR(pr.distance, d, 1e-6) << x;
    EXPECT_LE(pr.distance, d + 1e-12) << x;
    expect_consistent(x, pr, 1e-11);
    // Gap sign: the tooth (material) is at smaller polar angle than the flank at that radius.
    if (!pr.at_end && pr.distance > 1e-6)
    {
      const double r = x.norm();
      if (r > rb && r < rb * std::sqrt(1.36))
      {
        const double u = std::sqrt(r * r / (rb * rb) - 1.0);
        const double flank_angle = beta0 - (u - std::atan(u));
        EXPECT_EQ(pr.gap > 0.0, std::atan2(x[1], x[0]) > flank_angle) << x;
      }
    }
  }
}

TEST(CurveChain, InvoluteGearDie)
{
  using ausroll::geometry::InvoluteGear;
  using ausroll::geometry::ToothProportions;
  for (const bool fillet : {false, true})
    for (const unsigned int z : {31u, 57u}) // root below / above the base circle
    {
      ToothProportions prop;
      prop.root_fillet_radius = fillet ? 0.6 : 0.0;
      const InvoluteGear g = InvoluteGear::from_diametral_pitch(z, 8.5, 22.0 * M_PI / 180.0, prop);
      const double       axis = 0.25;
      const CurveChain   die = involute_gear_chain(g, axis);
      EXPECT_TRUE(die.is_closed());
      // Perimeter of the exact gear vs a fine polygon of the sampled outline.
      const auto outline = g.gear_outline(0.01, axis);
      double     perimeter = 0.0;
      for (std::size_t i = 0; i < outline.points.size(); ++i)
      {
        const Point<2> &a = outline.points[i];
        perimeter += a.distance(outline.points[(i + 1) % outline.points.size()]);
        if (i % 7 == 0) // every sampled outline point lies on the exact die (band search)
        {
          EXPECT_LT(std::abs(die.project(a, 0.1).gap), 1e-10) << a;
        }
      }
      EXPECT_NEAR(die.total_length(), perimeter, 1e-4 * perimeter);
      EXPECT_GT(die.total_length(), perimeter);
      // Material inside: the tooth axis point halfway up is inside, the space centre outside.
      const double     rm = 0.5 * (g.root_radius() + g.tip_radius());
      const Projection in = die.project(Point<2>(rm * std::cos(axis), rm * std::sin(axis)));
      EXPECT_LT(in.gap, 0.0);
      EXPECT_NEAR(in.gap, -g.tooth_thickness(rm) / 2.0, 0.05 * g.tooth_thickness(rm));
      const double     as = axis + M_PI / z;
      const Projection out = die.project(Point<2>(rm * std::cos(as), rm * std::sin(as)));
      EXPECT_GT(out.gap, 0.0);
      // Far outside and at the centre.
      EXPECT_NEAR(die.project(Point<2>()).gap, -g.root_radius(), 1e-9);
      const Projection far = die.project(Point<2>(0.0, 3.0 * g.tip_radius()));
      EXPECT_GT(far.gap, 1.9 * g.tip_radius());
      // Pitch point on a tooth flank: gap 0, normal = flank normal (rotated by the axis).
      const Point<2>   fp = g.flank_point(g.pitch_radius(), ausroll::geometry::FlankSide::positive);
      const Point<2>   x(std::cos(axis) * fp[0] - std::sin(axis) * fp[1],
                       std::sin(axis) * fp[0] + std::cos(axis) * fp[1]);
      const Projection pp = die.project(x);
      const Tensor<1, 2> nf
          = g.flank_normal(g.pitch_radius(), ausroll::geometry::FlankSide::positive);
      EXPECT_NEAR(pp.gap, 0.0, 1e-11);
      EXPECT_NEAR(pp.normal[0], std::cos(axis) * nf[0] - std::sin(axis) * nf[1], 1e-10);
      EXPECT_NEAR(pp.normal[1], std::sin(axis) * nf[0] + std::cos(axis) * nf[1], 1e-10);
      EXPECT_EQ(die.segment(die.segment_index(pp.coordinates[0])).type(),
                CurveSegment::Type::involute);
    }
}

TEST(CurveChain, GearSectorAndRandomPoints)
{
  using ausroll::geometry::InvoluteGear;
  using ausroll::geometry::ToothProportions;
  ToothProportions prop;
  prop.root_fillet_radius = 0.4;
  const InvoluteGear g = InvoluteGear::from_diametral_pitch(31, 8.5, 22.0 * M_PI / 180.0, prop);
  const double       axis = M_PI / 2.0;
  const CurveChain   sector = involute_gear_chain(g, axis, 3);
  EXPECT_FALSE(sector.is_closed());
  // Starts and ends on the root circle in the middle of the spaces around the 3 teeth.
  const double half_sector = 1.5 * g.angular_pitch();
  EXPECT_NEAR(sector.point_at(sector.s_begin())
                  .distance(Point<2>(g.root_radius() * std::cos(axis + half_sector),
                                     g.root_radius() * std::sin(axis + half_sector))),
              0.0,
              1e-10);
  EXPECT_NEAR(sector.point_at(sector.s_end())
                  .distance(Point<2>(g.root_radius() * std::cos(axis - half_sector),
                                     g.root_radius() * std::sin(axis - half_sector))),
              0.0,
              1e-10);
  EXPECT_NEAR(sector.total_length() * 31.0 / 3.0, involute_gear_chain(g).total_length(), 1e-9);
  // Random points near the middle tooth: exact distance vs dense sampling, and consistency.
  std::mt19937                           rng(7);
  std::uniform_real_distribution<double> ur(g.root_radius() - 1.0, g.tip_radius() + 1.0),
      ua(axis - 0.08, axis + 0.08);
  for (unsigned int k = 0; k < 200; ++k)
  {
    const double     r = ur(rng), a = ua(rng);
    const Point<2>   x(r * std::cos(a), r * std::sin(a));
    const Projection pr = sector.project(x);
    EXPECT_NEAR(pr.distance, brute_force_distance(sector, x, 4000), 1e-5) << x;
    expect_consistent(x, pr, 1e-11);
    // Search band consistent with the full search.
    const Projection banded = sector.project(x, pr.distance + 0.1);
    ASSERT_TRUE(banded.valid);
    EXPECT_NEAR(banded.gap, pr.gap, 1e-14);
  }
}

TEST(CurveChain, InvalidChainsThrow)
{
  EXPECT_THROW(CurveChain({CurveSegment::line(Point<2>(0, 0), Point<2>(1, 0)),
                           CurveSegment::line(Point<2>(1, 0.1), Point<2>(2, 0))},
                          false),
               ausroll::InputError);
  EXPECT_THROW(polyline_chain({Point<2>(0, 0), Point<2>(0, 0)}), std::runtime_error);
  EXPECT_THROW(circle_chain(Point<2>(), -1.0), ausroll::InputError);
}
