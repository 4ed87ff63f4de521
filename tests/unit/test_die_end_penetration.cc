/**
 * @file test_die_end_penetration.cc
 * The "inside the die" decision of the non-candidate penetration check (DieProjection::depth(),
 * from Projection / SurfaceProjection::end_margin) for nodes near and beyond the end of an open,
 * finite die: the dies of prm/head_forming.prm in 2D (polylines, extended to infinity for the
 * contact) and revolved in 3D, an extruded finite profile, and the unchanged answer of infinite
 * and closed dies. Every expected value is the hand-computed distance of the point to the die's
 * surface or to the die's end (the points lie on axis-parallel lines through the die points), so
 * the tolerance is round-off (1e-12).
 */
#include <ausroll/contact/contact_parameters.h>
#include <ausroll/contact/rigid_die.h>
#include <ausroll/contact/surfaces/arc_line.h>
#include <ausroll/contact/surfaces/circle.h>
#include <ausroll/contact/surfaces/flat.h>
#include <ausroll/contact/surfaces/polyline.h>
#include <ausroll/geometry/curve_chain.h>

#include "contact_test_utilities.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

using namespace dealii;
using namespace ausroll;
using ausroll::testing::parse_die;

namespace
{
  constexpr double tol = 1e-12;

  /** The depth of @p x in @p die at t = 0 (the projection must be valid). */
  template <int dim>
  double depth(const contact::RigidDie<dim> &die, const Point<dim> &x)
  {
    const contact::DieProjection<dim> p = die.project(x, 0.);
    EXPECT_TRUE(p.valid) << x;
    return p.depth();
  }

  /** The 3D point at radius @p r, height @p z and polar angle @p theta about the z axis. */
  Point<3> revolved(const double r, const double z, const double theta)
  {
    return Point<3>(r * std::cos(theta), r * std::sin(theta), z);
  }

  // The two dies of prm/head_forming.prm around the top of the bore (r = x, z = y): the bore
  // wall r = 10 for -1 <= z <= 10 (material at r > 10) and the shoulder z = 10 for
  // 10 <= r <= 40 (material below).
  const std::string bore_2d
      = "set Shape = polyline\nset Search distance = 3\nsubsection Polyline\nset Points = 10, -1; "
        "10, 10\nend\n";
  const std::string shoulder_2d
      = "set Shape = polyline\nset Search distance = 3\nsubsection Polyline\nset Points = 10, 10; "
        "40, 10\nend\n";
} // namespace

// The bug of prm/head_forming.prm: the free surface above the bore bulges out to r > 10 above
// z = 10, on the polyline's extension to infinity; it is not inside the bore die. The depth is
// min(-gap, end margin): the end margin is the distance along the wall to its end z = 10.
TEST(DieEndPenetration, PolylineBeyondItsEnd2d)
{
  const contact::RigidDie<2> bore(parse_die(bore_2d), 0);
  // beyond the end, on the material side (gap -0.05, 2 mm past the end): not inside
  EXPECT_NEAR(depth(bore, Point<2>(10.05, 12.)), -2., tol);
  EXPECT_NEAR(bore.project(Point<2>(10.05, 12.), 0.).gap, -0.05, tol);
  // level with the end point: at the rim, not inside
  EXPECT_NEAR(depth(bore, Point<2>(10.05, 10.)), 0., tol);
  // behind the wall, 5 mm from its top end and 6 mm from its bottom end: inside by the gap
  EXPECT_NEAR(depth(bore, Point<2>(10.05, 5.)), 0.05, tol);
  // in front of the wall: outside
  EXPECT_NEAR(depth(bore, Point<2>(9.5, 5.)), -0.5, tol);

  const contact::RigidDie<2> shoulder(parse_die(shoulder_2d), 0);
  // the node of the bore's lateral surface 2 mm below the shoulder's end point (the false
  // warning with `Penetrating boundaries = warn`): on the end's normal line or on the
  // extension, not inside
  EXPECT_NEAR(depth(shoulder, Point<2>(10., 8.)), 0., tol);
  EXPECT_NEAR(depth(shoulder, Point<2>(9.999, 8.)), -0.001, tol);
  // held 0.004 mm into the bore wall, 1 mm below the shoulder: 0.004 mm from the die's end, far
  // less than the check's tolerance (1e-2 of the 1 mm cells)
  EXPECT_NEAR(depth(shoulder, Point<2>(10.004, 9.)), 0.004, tol);
  // under the shoulder's face, away from its ends: inside by the gap
  EXPECT_NEAR(depth(shoulder, Point<2>(20., 9.5)), 0.5, tol);
  EXPECT_NEAR(depth(shoulder, Point<2>(39.8, 9.5)), 0.2, tol);
}

// Infinite and closed dies behave as before: the depth is -gap wherever the point is.
TEST(DieEndPenetration, InfiniteAndClosedDiesUnchanged2d)
{
  const contact::RigidDie<2> flat(
      parse_die("set Shape = flat\nsubsection Flat\nset Point = 0, 30\nset Normal = 0, -1\nend\n"),
      0);
  EXPECT_NEAR(depth(flat, Point<2>(1000., 31.)), 1., tol);
  EXPECT_EQ(flat.project(Point<2>(1000., 31.), 0.).end_margin,
            std::numeric_limits<double>::infinity());
  const contact::RigidDie<2> roll(
      parse_die("set Shape = circle\nsubsection Circle\nset Center = 0, 0\nset Radius = 5\nend\n"),
      0);
  EXPECT_NEAR(depth(roll, Point<2>(0., -4.)), 1., tol);
  EXPECT_NEAR(depth(roll, Point<2>(0., 6.)), -1., tol);
}

// The chain itself: the outline of an extended polyline and line-arc composite is the part
// between the given points (also when travelled backwards); an open chain without extensions
// ends at its end points (a clamped projection has margin 0 whatever the gap's sign).
TEST(DieEndPenetration, OutlineMarginOfChains)
{
  using contact::surfaces::arc_line_chain;
  using contact::surfaces::circle_chain;
  using contact::surfaces::flat_chain;
  using contact::surfaces::polyline_chain;
  using geometry::CurveChain;
  const std::vector<Point<2>> points{Point<2>(0., 0.), Point<2>(10., 0.), Point<2>(10., 10.)};

  const CurveChain extended = polyline_chain(points, false, true);
  EXPECT_NEAR(extended.project(Point<2>(5., -1.)).end_margin, 5., tol);
  EXPECT_NEAR(extended.project(Point<2>(-3., -1.)).end_margin, -3., tol);
  EXPECT_NEAR(extended.project(Point<2>(10.5, 12.)).end_margin, -2., tol);
  EXPECT_NEAR(extended.project(Point<2>(10.5, 9.)).end_margin, 1., tol);
  // backwards: the same outline, the same margins
  const CurveChain back = extended.reversed();
  EXPECT_NEAR(back.project(Point<2>(-3., 1.)).end_margin, -3., tol);
  EXPECT_NEAR(back.project(Point<2>(9.5, 9.)).end_margin, 1., tol);

  const CurveChain open = polyline_chain(points);
  const auto       beyond = open.project(Point<2>(11., 12.)); // past the end, material side
  EXPECT_TRUE(beyond.at_end);
  EXPECT_LT(beyond.gap, 0.);
  EXPECT_NEAR(beyond.end_margin, 0., tol);
  EXPECT_NEAR(open.project(Point<2>(10.5, 9.)).end_margin, 1., tol);

  // fillet 2 at (10, 0): outline length 8 + pi + 8; (10.5, 9) lies 1 before its end
  const CurveChain arc_line = arc_line_chain(points, {2.}, false, true);
  EXPECT_NEAR(arc_line.project(Point<2>(10.5, 9.)).end_margin, 1., tol);
  EXPECT_NEAR(arc_line.project(Point<2>(10.5, 13.)).end_margin, -3., tol);
  EXPECT_NEAR(arc_line.project(Point<2>(-1., -1.)).end_margin, -1., tol);
  EXPECT_NEAR(arc_line.project(Point<2>(4., -1.)).end_margin, 4., tol);

  EXPECT_EQ(
      flat_chain(Point<2>(0., 0.), Tensor<1, 2>({1., 0.})).project(Point<2>(1e6, -1.)).end_margin,
      std::numeric_limits<double>::infinity());
  EXPECT_EQ(circle_chain(Point<2>(0., 0.), 5.).project(Point<2>(1., 0.)).end_margin,
            std::numeric_limits<double>::infinity());
}

// The 3D analogue: the head-forming dies as revolved profiles at three polar angles (the bore
// wall extended to infinity like the 2D polyline; the shoulder, which may not be extended across
// the axis, ends at its points); an extruded finite profile (rims at the profile's ends and at
// Start z / End z); the unbounded plane unchanged and a finite rectangle (rims at its edges).
TEST(DieEndPenetration, RevolvedAndExtrudedProfiles3d)
{
  const auto revolved_die = [](const std::string &points, const bool extend)
  {
    return contact::RigidDie<3>(
        parse_die("set Shape = revolved profile\nset Search distance = 3\nsubsection Revolved "
                  "profile\nsubsection Profile\nset Type = polyline\nset Extend ends = "
                  + std::string(extend ? "true" : "false")
                  + "\nsubsection Polyline\nset Points = " + points + "\nend\nend\nend\n"),
        0);
  };
  const contact::RigidDie<3> bore = revolved_die("10, -1; 10, 10", true);
  const contact::RigidDie<3> shoulder = revolved_die("10, 10; 40, 10", false);
  for (const double theta : {0., 1.1, -2.7})
  {
    EXPECT_NEAR(depth(bore, revolved(10.05, 12., theta)), -2., tol);
    EXPECT_NEAR(depth(bore, revolved(10.05, 10., theta)), 0., tol);
    EXPECT_NEAR(depth(bore, revolved(10.05, 5., theta)), 0.05, 1e-11);
    EXPECT_NEAR(depth(shoulder, revolved(10., 8., theta)), 0., tol);
    EXPECT_NEAR(depth(shoulder, revolved(9.999, 8., theta)), 0., tol); // clamped to the rim
    EXPECT_NEAR(depth(shoulder, revolved(20., 9.5, theta)), 0.5, tol);
  }
  // a profile end on the axis is no rim: a disk z = 10, r <= 40, material below
  const contact::RigidDie<3> disk = revolved_die("0, 10; 40, 10", false);
  EXPECT_NEAR(depth(disk, revolved(0.01, 9.5, 0.3)), 0.5, tol);

  // extruded: the profile y = 0, 0 <= x <= 10 (material below), z in [0, 5], open ends
  const contact::RigidDie<3> plate(
      parse_die("set Shape = extruded profile\nsubsection Extruded profile\nset Extent = "
                "finite\nset Start z = 0\nset End z = 5\nsubsection Profile\nset Type = "
                "polyline\nsubsection Polyline\nset Points = 0, 0; 10, 0\nend\nend\nend\n"),
      0);
  EXPECT_NEAR(depth(plate, Point<3>(5., -0.5, 2.)), 0.5, tol);
  EXPECT_NEAR(depth(plate, Point<3>(5., -0.5, 4.8)), 0.2, tol); // 0.2 from End z
  EXPECT_NEAR(depth(plate, Point<3>(9.7, -0.5, 2.)), 0.3, tol); // 0.3 from the profile's end
  EXPECT_LE(depth(plate, Point<3>(5., -0.5, 6.)), 0.);          // beyond End z
  EXPECT_LE(depth(plate, Point<3>(11., -0.5, 2.)), 0.);         // beyond the profile's end

  const contact::RigidDie<3> plane(parse_die("set Shape = plane\n"), 0);
  const Point<3>             below(1e4, -1e4, -1.);
  EXPECT_NEAR(depth(plane, below), -plane.project(below, 0.).gap, tol);
  EXPECT_GT(depth(plane, below), 0.);

  // a finite rectangle |x| <= 4, |y| <= 2 in z = 0 (material below): rims at its edges
  const contact::RigidDie<3> platen(
      parse_die("set Shape = plane\nsubsection Plane\nset First tangent = 1, 0, 0\nset Half "
                "length 1 = 4\nset Half length 2 = 2\nend\n"),
      0);
  EXPECT_NEAR(depth(platen, Point<3>(0., 0., -0.5)), 0.5, tol);
  EXPECT_NEAR(depth(platen, Point<3>(3.8, 0., -0.5)), 0.2, tol);  // 0.2 from the edge x = 4
  EXPECT_NEAR(depth(platen, Point<3>(1., -1.7, -0.5)), 0.3, tol); // 0.3 from the edge y = -2
  EXPECT_LE(depth(platen, Point<3>(4.5, 0., -0.5)), 0.);          // beside the rectangle
}
