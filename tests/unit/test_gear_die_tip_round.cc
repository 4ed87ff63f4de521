/**
 * @file test_gear_die_tip_round.cc
 * Unit tests of the tip rounds of the involute gear die (CurveChain::involute_gear with
 * tip_round > 0, die entry `Tip radius`): tangent continuity, and the round checked against
 * independent references: its centre lies at the distance tip_round from the sharp involute
 * (brute-force minimum over the flank) and from the outside circle.
 */
#include <ausroll/contact/surfaces/involute_gear.h>
#include <ausroll/geometry/curve_chain.h>
#include <ausroll/geometry/involute_gear.h>

#include <gtest/gtest.h>

#include <cmath>

using ausroll::contact::surfaces::involute_gear_chain;
using ausroll::geometry::CurveChain;
using ausroll::geometry::CurveSegment;
using ausroll::geometry::FlankSide;
using ausroll::geometry::InvoluteGear;
using ausroll::geometry::ToothProportions;
using dealii::Point;

namespace
{
  /** The thesis die gear: 57 teeth, DP 8.5, PA 22 deg, outside diameter 6.882". */
  InvoluteGear thesis_die()
  {
    ToothProportions p;
    p.addendum = 2.23677;
    return InvoluteGear::from_diametral_pitch(57, 8.5, 22.0 * M_PI / 180.0, p);
  }

  Point<2> rotated(const Point<2> &p, const double a)
  {
    return Point<2>(std::cos(a) * p[0] - std::sin(a) * p[1],
                    std::sin(a) * p[0] + std::cos(a) * p[1]);
  }

  /** Distance of @p x from the sharp positive flank of the tooth with axis angle @p a: minimum
   * over 20001 flank points, refined by golden-section search on the radius. */
  double distance_to_flank(const InvoluteGear &g, const Point<2> &x, const double a)
  {
    const double r0 = g.base_radius(), r1 = g.tip_radius();
    const auto   dist = [&](const double r)
    { return x.distance(rotated(g.flank_point(r, FlankSide::positive), a)); };
    const unsigned n = 20000;
    unsigned       best = 0;
    for (unsigned i = 1; i <= n; ++i)
      if (dist(r0 + (r1 - r0) * i / n) < dist(r0 + (r1 - r0) * best / n))
        best = i;
    double       lo = r0 + (r1 - r0) * (best > 0 ? best - 1.0 : 0.0) / n;
    double       hi = r0 + (r1 - r0) * std::min(best + 1.0, double(n)) / n;
    const double gr = 0.5 * (std::sqrt(5.0) - 1.0);
    for (int k = 0; k < 100; ++k)
    {
      const double m1 = hi - gr * (hi - lo), m2 = lo + gr * (hi - lo);
      if (dist(m1) < dist(m2))
        hi = m2;
      else
        lo = m1;
    }
    return dist(0.5 * (lo + hi));
  }
} // namespace

TEST(GearDieTipRound, TangentToFlankAndOutsideCircle)
{
  const InvoluteGear g = thesis_die();
  const double       axis = 0.3;
  const CurveChain   sharp = involute_gear_chain(g, axis, 1);
  for (const double rho : {0.1, 0.4, 0.8})
  {
    SCOPED_TRACE(rho);
    const CurveChain die = involute_gear_chain(g, axis, 1, rho);
    ASSERT_EQ(die.n_segments(), sharp.n_segments() + 2);
    const auto is_round = [&](const unsigned int i)
    {
      const CurveSegment &s = die.segment(i);
      return s.type() == CurveSegment::Type::arc && std::abs(s.curvature(0.0) * rho - 1.0) < 1e-9;
    };
    unsigned int n_rounds = 0;
    for (unsigned int i = 0; i < die.n_segments(); ++i)
    {
      const CurveSegment &s = die.segment(i);
      // G1: both ends of a round join tangentially (flank -> round -> tip land -> round -> flank;
      // the root corners of this fillet-less die stay sharp).
      if (i + 1 < die.n_segments() && (is_round(i) || is_round(i + 1)))
      {
        const auto t0 = s.tangent(s.u_end());
        const auto t1 = die.segment(i + 1).tangent(die.segment(i + 1).u_begin());
        EXPECT_LT((t0 - t1).norm(), 1e-9) << "joint " << i;
      }
      if (!is_round(i))
        continue;
      ++n_rounds;
      const Point<2> c = s.point(s.u_begin()) - rho * s.normal(s.u_begin());
      EXPECT_LT(c.distance(s.point(s.u_end()) - rho * s.normal(s.u_end())), 1e-10);
      // Independent references: the centre lies rho inside the outside circle and rho from the
      // sharp involute flank (brute-force distance; the negative-flank round by symmetry).
      EXPECT_NEAR(g.tip_radius() - c.norm(), rho, 1e-10);
      const double   phi = std::atan2(c[1], c[0]) - axis;
      const Point<2> c_pos = rotated(
          Point<2>(c.norm() * std::cos(std::abs(phi)), c.norm() * std::sin(std::abs(phi))), axis);
      EXPECT_NEAR(distance_to_flank(g, c_pos, axis), rho, 1e-8);
      // No point of the round lies outside the outside circle; its end on it is the tip.
      for (int k = 0; k <= 20; ++k)
        EXPECT_LE(s.point(s.u_begin() + k * s.length() / 20).norm(), g.tip_radius() + 1e-10);
    }
    EXPECT_EQ(n_rounds, 2u);
    // The sharp tip corner is cut off: it lies outside the rounded die at |P - c| - rho.
    const Point<2> corner = rotated(g.flank_point(g.tip_radius(), FlankSide::positive), axis);
    EXPECT_LT(std::abs(sharp.project(corner).gap), 1e-10);
    EXPECT_GT(die.project(corner).gap, 0.0);
    // Far from the tip (pitch point) the flank is unchanged.
    const Point<2> pitch = rotated(g.flank_point(g.pitch_radius(), FlankSide::positive), axis);
    EXPECT_LT(std::abs(die.project(pitch).gap), 1e-10);
  }
}

TEST(GearDieTipRound, BadRadius)
{
  const InvoluteGear g = thesis_die();
  EXPECT_ANY_THROW(involute_gear_chain(g, 0.0, 1, -0.1));
  // A round wider than the tip land (tip thickness about 2.2 mm) leaves no land.
  EXPECT_ANY_THROW(involute_gear_chain(g, 0.0, 1, 3.0));
  EXPECT_NO_THROW(involute_gear_chain(g, 0.0, 0, 0.5));
}
