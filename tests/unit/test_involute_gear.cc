/**
 * @file test_involute_gear.cc
 * Unit tests of geometry::InvoluteGear: radii against the thesis gear data, the involute function,
 * tooth thickness, flank points and normals, root fillet and sampled outlines.
 */
#include <ausroll/core/exceptions.h>
#include <ausroll/geometry/involute_gear.h>

#include <gtest/gtest.h>

#include <cmath>

using ausroll::geometry::FlankSide;
using ausroll::geometry::InvoluteGear;
using ausroll::geometry::mm_per_inch;
using ausroll::geometry::OutlinePart;
using ausroll::geometry::ToothOutline;
using ausroll::geometry::ToothProportions;
using dealii::Point;
using dealii::Tensor;

namespace
{
  const double deg = M_PI / 180.0;

  /** Thesis workpiece gear: 31 teeth, DP 8.5, PA 22 degrees. */
  InvoluteGear thesis_workpiece(const ToothProportions &p = ToothProportions())
  {
    return InvoluteGear::from_diametral_pitch(31, 8.5, 22.0 * deg, p);
  }

  /** Thesis die gear: 57 teeth, DP 8.5, PA 22 degrees. */
  InvoluteGear thesis_die(const ToothProportions &p = ToothProportions())
  {
    return InvoluteGear::from_diametral_pitch(57, 8.5, 22.0 * deg, p);
  }

  /** Diameter in inches of a radius in mm. */
  double inches(const double radius_mm)
  {
    return 2.0 * radius_mm / mm_per_inch;
  }

  double polar(const Point<2> &p)
  {
    return std::atan2(p[1], p[0]);
  }
} // namespace

// The thesis prints diameters with 4-5 significant digits: compare to 2e-4 inch (~ 5e-5 relative).
TEST(InvoluteGear, ThesisWorkpieceGearNumbers)
{
  const InvoluteGear g = thesis_workpiece();
  const double       tol = 2e-4;
  EXPECT_NEAR(g.module(), 25.4 / 8.5, 1e-14);
  EXPECT_NEAR(g.diametral_pitch(), 8.5, 1e-12);
  EXPECT_NEAR(inches(g.pitch_radius()), 3.6471, tol);
  EXPECT_NEAR(inches(g.pitch_radius()), 31.0 / 8.5, 1e-12); // pitch D = z / P_d exactly
  EXPECT_NEAR(inches(g.base_radius()), 3.3816, tol);
  EXPECT_NEAR(g.base_radius(), g.pitch_radius() * std::cos(22.0 * deg), 1e-12);
  EXPECT_NEAR(g.tooth_thickness(g.pitch_radius()) / mm_per_inch, 0.1848, 5e-5);
  EXPECT_NEAR(inches(g.tip_radius()), 33.0 / 8.5, 1e-12);  // default addendum 1 / P_d
  EXPECT_NEAR(inches(g.root_radius()), 28.5 / 8.5, 1e-12); // default dedendum 1.25 / P_d
  EXPECT_NEAR(g.circular_pitch() / mm_per_inch, M_PI / 8.5, 1e-12);
}

TEST(InvoluteGear, ThesisDieGearNumbers)
{
  const double       tol = 2e-4;
  const InvoluteGear g = thesis_die();
  EXPECT_NEAR(inches(g.pitch_radius()), 6.7059, tol);
  EXPECT_NEAR(inches(g.base_radius()), 6.2176, tol);
  // The thesis die has an outside diameter of 6.882", i.e. a shortened addendum of
  // (6.882 - 57/8.5)/2 = 0.0881" instead of the full-depth 1/P_d = 0.1176" (OD 6.9412").
  EXPECT_NEAR(inches(g.tip_radius()), 6.9412, tol);
  ToothProportions stub;
  stub.addendum = 0.5 * (6.882 - 57.0 / 8.5) * mm_per_inch;
  const InvoluteGear die = thesis_die(stub);
  EXPECT_NEAR(inches(die.tip_radius()), 6.882, 1e-12);
  EXPECT_NEAR(inches(die.base_radius()), 6.2176, tol);
}

TEST(InvoluteGear, InvoluteFunction)
{
  // Table values: inv(20 deg) = 0.014904, inv(22 deg) = 0.020054.
  EXPECT_NEAR(InvoluteGear::involute(20.0 * deg), 0.0149044, 1e-7);
  EXPECT_NEAR(InvoluteGear::involute(22.0 * deg), 0.0200538, 1e-7);
  EXPECT_EQ(InvoluteGear::involute(0.0), 0.0);
  for (const double a : {1e-3, 0.1, 22.0 * deg, 0.7, 1.2, 1.5})
    EXPECT_NEAR(InvoluteGear::inverse_involute(InvoluteGear::involute(a)), a, 1e-12 * (1.0 + a));
}

TEST(InvoluteGear, InvolutePointLiesOnItsRadius)
{
  const double rb = 10.0;
  for (const double u : {0.0, 0.2, 0.5, 1.0})
  {
    const Point<2> p = InvoluteGear::involute_point(rb, u);
    EXPECT_NEAR(p.norm(), rb * std::sqrt(1.0 + u * u), 1e-12);
    EXPECT_NEAR(polar(p), u - std::atan(u), 1e-12); // polar angle inv(alpha_r)
  }
}

TEST(InvoluteGear, ThicknessAtPitchEqualsInput)
{
  ToothProportions p;
  p.pitch_tooth_thickness = 4.2;
  const InvoluteGear g(20, 3.0, 20.0 * deg, p);
  EXPECT_NEAR(g.tooth_thickness(g.pitch_radius()), 4.2, 1e-12);
  EXPECT_NEAR(g.half_thickness_angle(g.pitch_radius()), 4.2 / (2.0 * g.pitch_radius()), 1e-14);
  // Thickness decreases outwards along the involute; radial flank below the base circle.
  EXPECT_GT(g.tooth_thickness(g.base_radius()) / g.base_radius(),
            g.tooth_thickness(g.tip_radius()) / g.tip_radius());
  EXPECT_NEAR(g.half_thickness_angle(0.99 * g.base_radius()),
              g.half_thickness_angle(g.base_radius()),
              1e-15);
  // s(r) = 2 r (s_p / (2 r_p) + inv(alpha) - inv(alpha_r))
  const double r = 0.5 * (g.pitch_radius() + g.tip_radius());
  const double a = std::acos(g.base_radius() / r);
  EXPECT_NEAR(g.tooth_thickness(r),
              2.0 * r
                  * (4.2 / (2.0 * g.pitch_radius()) + InvoluteGear::involute(20.0 * deg)
                     - InvoluteGear::involute(a)),
              1e-12);
}

TEST(InvoluteGear, FlankIsMirroredRotatedInvolute)
{
  const InvoluteGear g = thesis_workpiece();
  const double       beta0 = g.tooth_geometry().base_half_angle;
  for (const double r : {g.base_radius(), g.pitch_radius(), g.tip_radius()})
  {
    const double   u = g.roll_angle_at(r);
    const Point<2> q = InvoluteGear::involute_point(g.base_radius(), u);
    // Positive flank = standard involute mirrored about x and rotated by beta_0.
    const Point<2> expected(std::cos(beta0) * q[0] + std::sin(beta0) * q[1],
                            std::sin(beta0) * q[0] - std::cos(beta0) * q[1]);
    const Point<2> p = g.flank_point(r, FlankSide::positive);
    EXPECT_NEAR(p[0], expected[0], 1e-12);
    EXPECT_NEAR(p[1], expected[1], 1e-12);
    const Point<2> m = g.flank_point(r, FlankSide::negative);
    EXPECT_NEAR(m[0], p[0], 1e-15);
    EXPECT_NEAR(m[1], -p[1], 1e-15);
  }
}

TEST(InvoluteGear, FlankNormalIsPerpendicularAndAlongLineOfAction)
{
  const InvoluteGear g = thesis_workpiece();
  for (const FlankSide side : {FlankSide::positive, FlankSide::negative})
    for (const double r : {g.pitch_radius(), 0.5 * (g.base_radius() + g.tip_radius())})
    {
      const double       h = 1e-6;
      const Tensor<1, 2> tangent
          = (g.flank_point(r + h, side) - g.flank_point(r - h, side)) / (2.0 * h);
      const Tensor<1, 2> n = g.flank_normal(r, side);
      EXPECT_NEAR(n.norm(), 1.0, 1e-14);
      EXPECT_NEAR(n * tangent / tangent.norm(), 0.0, 1e-8);
      // The normal line is tangent to the base circle: distance from the centre = r_b.
      const Point<2> p = g.flank_point(r, side);
      EXPECT_NEAR(std::abs(p[0] * n[1] - p[1] * n[0]), g.base_radius(), 1e-10);
      // It points out of the tooth (into the space).
      const Tensor<1, 2> e_theta({-p[1] / r, p[0] / r});
      EXPECT_GT((side == FlankSide::positive ? 1.0 : -1.0) * (n * e_theta), 0.0);
    }
}

TEST(InvoluteGear, RootFilletIsTangentToRootAndFlank)
{
  // Workpiece (root below the base circle) with a small fillet that leaves a radial flank piece
  // and with a larger one that meets the involute; die gear (root above the base circle).
  const double m = 25.4 / 8.5;
  for (const auto &[die, fillet] :
       {std::pair{false, 0.02 * m}, {false, 0.25 * m}, {true, 0.25 * m}})
  {
    ToothProportions p;
    p.root_fillet_radius = fillet;
    const InvoluteGear g = die ? thesis_die(p) : thesis_workpiece(p);
    const auto        &t = g.tooth_geometry();
    const double       rf = p.root_fillet_radius;
    EXPECT_EQ(t.has_radial_flank, !die && fillet < 0.1 * m);
    EXPECT_EQ(t.has_radial_flank, t.flank_start_radius < g.base_radius());
    EXPECT_EQ(g.root_radius() < g.base_radius(), !die);
    EXPECT_NEAR(t.fillet_center.norm(), g.root_radius() + rf, 1e-10);
    const Point<2> q = g.flank_point(t.flank_start_radius, FlankSide::positive);
    EXPECT_NEAR(q.distance(t.fillet_center), rf, 1e-10);
    const Tensor<1, 2> n = g.flank_normal(t.flank_start_radius, FlankSide::positive);
    EXPECT_NEAR(((t.fillet_center - q) / rf) * n, 1.0, 1e-10);
    EXPECT_GT(t.flank_start_radius, g.root_radius());
    EXPECT_LT(t.root_land_angle, M_PI / g.n_teeth());
    EXPECT_NEAR(t.root_land_angle, polar(t.fillet_center), 1e-15);
  }
}

TEST(InvoluteGear, ToothOutlineGeometry)
{
  ToothProportions p;
  p.root_fillet_radius = 0.3;
  const InvoluteGear g = thesis_workpiece(p);
  const double       h = 0.05;
  const double       ax = 0.3;
  const ToothOutline out = g.tooth_outline(h, ax);
  ASSERT_EQ(out.parts.size() + 1, out.points.size());
  EXPECT_FALSE(out.closed);
  const double z = g.n_teeth();
  EXPECT_NEAR(out.points.front().norm(), g.root_radius(), 1e-12);
  EXPECT_NEAR(out.points.back().norm(), g.root_radius(), 1e-12);
  EXPECT_NEAR(polar(out.points.front()), ax - M_PI / z, 1e-12);
  EXPECT_NEAR(polar(out.points.back()), ax + M_PI / z, 1e-12);
  bool seen[5] = {false, false, false, false, false};
  for (std::size_t i = 0; i < out.parts.size(); ++i)
  {
    const Point<2> &a = out.points[i], &b = out.points[i + 1];
    EXPECT_LE(a.distance(b), h * (1.0 + 1e-9));
    EXPECT_GT(a.distance(b), 0.0);
    EXPECT_GE(a.norm(), g.root_radius() - 1e-12);
    EXPECT_LE(a.norm(), g.tip_radius() + 1e-12);
    EXPECT_GT(polar(b), polar(a) - 1e-9); // counter-clockwise
    seen[static_cast<int>(out.parts[i])] = true;
    // Points on the involute pieces lie on the flank at their radius.
    if (out.parts[i] == OutlinePart::involute_flank)
    {
      const double r = b.norm();
      const double expect = g.half_thickness_angle(r);
      EXPECT_NEAR(std::abs(polar(b) - ax), expect, 1e-12);
    }
    if (out.parts[i] == OutlinePart::tip_land)
    {
      EXPECT_NEAR(b.norm(), g.tip_radius(), 1e-12);
    }
  }
  for (const bool s : seen)
    EXPECT_TRUE(s);
  // Mirror symmetry about the tooth axis.
  const std::size_t n = out.points.size();
  for (std::size_t i = 0; i < n; ++i)
    EXPECT_NEAR(polar(out.points[i]) - ax, -(polar(out.points[n - 1 - i]) - ax), 1e-12);
}

TEST(InvoluteGear, GearOutlineIsClosed)
{
  const InvoluteGear g = thesis_die();
  const ToothOutline one = g.tooth_outline(0.2);
  const ToothOutline all = g.gear_outline(0.2);
  EXPECT_TRUE(all.closed);
  EXPECT_EQ(all.points.size(), all.parts.size());
  EXPECT_EQ(all.points.size(), g.n_teeth() * (one.points.size() - 1));
  // Perimeter: slightly below the analytic one; tooth pitch symmetry.
  double perimeter = 0.0;
  for (std::size_t i = 0; i < all.points.size(); ++i)
    perimeter += all.points[i].distance(all.points[(i + 1) % all.points.size()]);
  EXPECT_GT(perimeter, 2.0 * M_PI * g.root_radius());
  EXPECT_LT(perimeter, 2.0 * M_PI * g.tip_radius() + 4.0 * g.n_teeth() * g.addendum());
}

TEST(InvoluteGear, InvalidInputThrows)
{
  EXPECT_THROW(InvoluteGear(2, 1.0, 20.0 * deg), ausroll::InputError);
  EXPECT_THROW(InvoluteGear(20, -1.0, 20.0 * deg), ausroll::InputError);
  EXPECT_THROW(InvoluteGear(20, 1.0, 95.0 * deg), ausroll::InputError);
  ToothProportions pointed;
  pointed.addendum = 5.0; // the tooth ends in a point long before
  EXPECT_THROW(InvoluteGear(20, 1.0, 20.0 * deg, pointed), ausroll::InputError);
  ToothProportions big_fillet;
  big_fillet.root_fillet_radius = 2.0;
  EXPECT_THROW(InvoluteGear(20, 1.0, 20.0 * deg, big_fillet), ausroll::InputError);
  ToothProportions thick;
  thick.pitch_tooth_thickness = 4.0; // more than the circular pitch pi
  EXPECT_THROW(InvoluteGear(20, 1.0, 20.0 * deg, thick), std::runtime_error);
}

// Remaining thesis numbers: the 0.1848" pitch thickness is the standard half circular pitch
// pi / (2 P_d) = 0.18480"; the workpiece outside diameter (not printed in the thesis) is the
// full-depth (z + 2) / P_d = 3.8824"; the pressure angle at the pitch circle is 22 degrees, and
// the thickness at the base circle follows from the involute function: s_b = 2 r_b (s_p / (2 r_p)
// + inv(22 deg)) = 0.23915" (closed form evaluated independently with inv(22 deg) = 0.0200538).
TEST(InvoluteGear, ThesisThicknessAndInvoluteNumbers)
{
  const InvoluteGear g = thesis_workpiece();
  EXPECT_NEAR(g.pitch_tooth_thickness() / mm_per_inch, M_PI / (2.0 * 8.5), 1e-12);
  EXPECT_NEAR(g.pitch_tooth_thickness() / mm_per_inch, 0.1848, 5e-5);
  EXPECT_NEAR(inches(g.tip_radius()), 3.8824, 1e-4);
  EXPECT_NEAR(g.pressure_angle_at(g.pitch_radius()), 22.0 * deg, 1e-12);
  EXPECT_NEAR(g.roll_angle_at(g.pitch_radius()), std::tan(22.0 * deg), 1e-12);
  EXPECT_NEAR(g.tooth_thickness(g.base_radius()) / mm_per_inch, 0.23915, 1e-5);
  EXPECT_NEAR(g.half_thickness_angle(g.base_radius()),
              0.1848 * mm_per_inch / (2.0 * g.pitch_radius()) + 0.0200538,
              2e-6);
  // The involute function at the pressure angle of the die tip circle (OD 6.882"):
  // alpha_t = acos(6.2176 / 6.882) = 25.3836 deg, inv = tan - angle = 0.031457.
  const double alpha_t = std::acos(6.2176 / 6.882);
  EXPECT_NEAR(alpha_t / deg, 25.3836, 1e-4);
  EXPECT_NEAR(InvoluteGear::involute(alpha_t), 0.031457, 1e-6);
  // Die pitch thickness: standard half circular pitch as well.
  EXPECT_NEAR(
      thesis_die().tooth_thickness(thesis_die().pitch_radius()) / mm_per_inch, 0.1848, 5e-5);
}
