/**
 * @file test_die_motion.cc
 * Unit tests of contact::DiePose and the die motions: pose round trips, prescribed motion values
 * and velocities, and the planetary rolling kinematics (no slip at the pitch point for beta = 1,
 * slip speed, feed).
 */
#include <ausroll/contact/die_motion.h>
#include <ausroll/contact/motion/fixed.h>
#include <ausroll/contact/motion/prescribed.h>
#include <ausroll/contact/motion/rolling.h>
#include <ausroll/contact/surfaces/circle.h>
#include <ausroll/core/exceptions.h>
#include <ausroll/geometry/curve_chain.h>

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

using DieMotion = ausroll::contact::DieMotion<2>;
using DiePose = ausroll::contact::DiePose<2>;
using ausroll::contact::surfaces::circle_chain;
using ausroll::geometry::CurveChain;
using FixedPose = ausroll::contact::FixedPose<2>;
using PrescribedMotion = ausroll::contact::PrescribedMotion<2>;
using RollingMotion = ausroll::contact::RollingMotion<2>;
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

  /** Independent central difference of the global position of die point X. */
  Tensor<1, 2>
  finite_difference_velocity(const DieMotion &motion, const double t, const Point<2> &X)
  {
    const double h = 1e-5;
    return (motion.pose(t + h).to_global(X) - motion.pose(t - h).to_global(X)) / (2.0 * h);
  }

  /** Thesis gear pitch radii (mm): workpiece 31 teeth, die 57 teeth, DP 8.5. */
  const double R_G = 0.5 * 31.0 / 8.5 * 25.4;
  const double R_D = 0.5 * 57.0 / 8.5 * 25.4;
} // namespace

TEST(DiePose, KnownValuesAndRoundTrip)
{
  // Reference point (1, 0) placed at (1, 2), rotated by 90 degrees.
  const DiePose  pose(Point<2>(1.0, 2.0), 0.5 * M_PI, Point<2>(1.0, 0.0));
  const Point<2> x = pose.to_global(Point<2>(2.0, 0.0));
  EXPECT_NEAR(x[0], 1.0, 1e-15);
  EXPECT_NEAR(x[1], 3.0, 1e-15);
  const Tensor<1, 2> n = pose.rotate_vector_to_global(vec(0.0, 1.0));
  EXPECT_NEAR(n[0], -1.0, 1e-15);
  EXPECT_NEAR(n[1], 0.0, 1e-15);
  EXPECT_EQ(pose.angle(), 0.5 * M_PI);
  EXPECT_EQ(pose.reference_position(), Point<2>(1.0, 2.0));

  const DiePose general(Point<2>(-3.0, 0.7), 2.1, Point<2>(0.4, -1.2));
  for (const Point<2> &X : {Point<2>(0.0, 0.0), Point<2>(5.0, -2.0), Point<2>(-1e3, 7.0)})
  {
    const Point<2> back = general.to_local(general.to_global(X));
    EXPECT_NEAR(back[0], X[0], 1e-12 * (1.0 + X.norm()));
    EXPECT_NEAR(back[1], X[1], 1e-12 * (1.0 + X.norm()));
    const Tensor<1, 2> v = general.rotate_vector_to_local(general.rotate_vector_to_global(X));
    EXPECT_NEAR(v[0], X[0], 1e-12 * (1.0 + X.norm()));
    // Rigid: distances preserved.
    EXPECT_NEAR(general.to_global(X).distance(general.to_global(Point<2>(1.0, 1.0))),
                X.distance(Point<2>(1.0, 1.0)),
                1e-12 * (1.0 + X.norm()));
  }
  // The reference point maps to its position.
  EXPECT_NEAR(general.to_global(Point<2>(0.4, -1.2)).distance(Point<2>(-3.0, 0.7)), 0.0, 1e-15);
  // Identity pose.
  EXPECT_EQ(DiePose().to_global(Point<2>(3.0, 4.0)), Point<2>(3.0, 4.0));
}

TEST(DieMotion, FixedPose)
{
  const FixedPose fixed(DiePose(Point<2>(1.0, 1.0), 0.3));
  EXPECT_EQ(fixed.pose(7.0).angle(), 0.3);
  EXPECT_EQ(fixed.velocity(2.0, Point<2>(4.0, 4.0)).norm(), 0.0);
  EXPECT_EQ(fixed.angular_velocity(2.0), 0.0);
}

TEST(DieMotion, PrescribedTranslationAndRotation)
{
  // u(t) = (t, 0), phi(t) = 0.1 t about the pivot (0, 1) (rest position = pivot).
  const PrescribedMotion motion([](const double t) { return vec(t, 0.0); },
                                [](const double t) { return 0.1 * t; },
                                Point<2>(0.0, 1.0));
  const Point<2>         X(1.0, 1.0);
  const Point<2>         x = motion.pose(2.0).to_global(X);
  EXPECT_NEAR(x[0], 2.0 + std::cos(0.2), 1e-14);
  EXPECT_NEAR(x[1], 1.0 + std::sin(0.2), 1e-14);
  // v = u' + phi' k x (x - c) = (1, 0) + 0.1 (-sin 0.2, cos 0.2).
  const Tensor<1, 2> v = motion.velocity(2.0, X);
  EXPECT_NEAR(v[0], 1.0 - 0.1 * std::sin(0.2), 1e-8);
  EXPECT_NEAR(v[1], 0.1 * std::cos(0.2), 1e-8);
  EXPECT_NEAR(motion.angular_velocity(2.0), 0.1, 1e-8);
  // At t = 0 the local and global frames coincide.
  EXPECT_NEAR(motion.pose(0.0).to_global(X).distance(X), 0.0, 1e-15);

  // Separate rest position of the pivot: a roll of radius 10 whose centre (local origin) starts at
  // (0, 12) and moves down with speed 0.5.
  const PrescribedMotion press(
      [](const double t) { return vec(0.0, -0.5 * t); }, {}, Point<2>(), Point<2>(0.0, 12.0));
  const CurveChain roll = circle_chain(Point<2>(), 10.0);
  // Gap of the global point (0, 1) at t = 4: centre at (0, 10), gap = 9 - 10 = -1.
  EXPECT_NEAR(roll.project(press.pose(4.0).to_local(Point<2>(0.0, 1.0))).gap, -1.0, 1e-13);
  const Tensor<1, 2> vp = PrescribedMotion::constant_velocity(vec(2.0, -1.0)).velocity(3.0, X);
  EXPECT_NEAR(vp[0], 2.0, 1e-8);
  EXPECT_NEAR(vp[1], -1.0, 1e-8);
}

TEST(RollingMotion, PureRollingHasNoSlipAtThePitchPoint)
{
  for (const int direction : {1, -1})
  {
    RollingMotion::Data d;
    d.workpiece_center = Point<2>(2.0, -1.0);
    d.workpiece_radius = R_G;
    d.die_radius = R_D;
    d.initial_die_angle = 0.4;
    d.direction = direction;
    d.revolution_angle = [](const double t) { return 0.3 * t + 0.05 * t * t; };
    const RollingMotion motion(d);
    const CurveChain    die = circle_chain(Point<2>(), R_D);

    for (const double t : {0.0, 0.7, 2.5})
    {
      const Point<2> xc = motion.pitch_point(t);
      // The contact point lies on the workpiece circle, on the line of centres.
      EXPECT_NEAR(xc.distance(d.workpiece_center), R_G, 1e-12);
      const double psi = std::atan2(xc[1] - d.workpiece_center[1], xc[0] - d.workpiece_center[0]);
      EXPECT_NEAR(
          std::remainder(psi - (0.5 * M_PI + direction * (0.3 * t + 0.05 * t * t)), 2.0 * M_PI),
          0.0,
          1e-12);
      EXPECT_NEAR(motion.die_center(t).distance(d.workpiece_center), R_G + R_D, 1e-12);
      // ... and on the die circle: the pitch circles touch.
      const Point<2> X = motion.pose(t).to_local(xc);
      EXPECT_NEAR(die.project(X).gap, 0.0, 1e-11);
      // The die material point at the contact point does not move (relative to the fixed
      // workpiece): independent finite differences in time.
      const double       speed = (R_G + R_D) * (0.3 + 0.1 * t); // speed of the die centre
      const Tensor<1, 2> v = finite_difference_velocity(motion, t, X);
      EXPECT_LT(v.norm(), 1e-8 * speed) << "t = " << t << ", v = " << v;
      EXPECT_LT(motion.velocity(t, X).norm(), 1e-6 * speed);
      // The die centre itself moves with (R_G + R_D) dtheta_G/dt.
      EXPECT_NEAR(finite_difference_velocity(motion, t, Point<2>()).norm(), speed, 1e-6 * speed);
      // Absolute angular velocity: (1 + R_G / R_D) times the revolution rate.
      EXPECT_NEAR(
          motion.angular_velocity(t), direction * (1.0 + R_G / R_D) * (0.3 + 0.1 * t), 1e-6);
    }

    // Rolling: the die arc between the material points touching at t0 and t1 equals the
    // workpiece arc R_G (psi1 - psi0).
    const double   t0 = 0.2, t1 = 1.1;
    const Point<2> X0 = motion.pose(t0).to_local(motion.pitch_point(t0));
    const Point<2> X1 = motion.pose(t1).to_local(motion.pitch_point(t1));
    const double   die_arc
        = R_D
          * std::abs(std::remainder(std::atan2(X1[1], X1[0]) - std::atan2(X0[1], X0[0]), 2 * M_PI));
    const double workpiece_arc = R_G * (0.3 * (t1 - t0) + 0.05 * (t1 * t1 - t0 * t0));
    EXPECT_NEAR(die_arc, workpiece_arc, 1e-10 * workpiece_arc);
  }
}

TEST(RollingMotion, SlipAndFeed)
{
  RollingMotion::Data d;
  d.workpiece_radius = R_G;
  d.die_radius = R_D;
  d.beta = 0.25;
  d.revolution_angle = [](const double t) { return 0.3 * t; };
  d.slip_angle = [](const double t) { return 0.2 * t; };
  d.feed = [](const double t) { return 0.1 * t; };
  const RollingMotion motion(d);
  EXPECT_NEAR(motion.spin_angle(2.0), R_G / R_D * 0.6 + 0.75 * 0.4, 1e-14);
  EXPECT_NEAR(motion.pose(2.0).angle(), 0.6 + R_G / R_D * 0.6 + 0.75 * 0.4, 1e-14);
  EXPECT_NEAR(motion.center_distance(2.0), R_G + R_D - 0.2, 1e-13);

  const double     t = 1.5;
  const Point<2>   xc = motion.pitch_point(t);
  const Point<2>   X = motion.pose(t).to_local(xc);
  const CurveChain die = circle_chain(Point<2>(), R_D);
  // Feed 0.15 moves the die into the workpiece pitch circle: penetration 0.15.
  EXPECT_NEAR(die.project(X).gap, -0.15, 1e-11);
  // Velocity of the die material point at the pitch point: rigid-body formula
  // v = dc/dt + omega k x (x - c) with omega = (1 + R_G/R_D) dtheta_G/dt + (1 - beta) dtheta_s/dt.
  const Tensor<1, 2> v = finite_difference_velocity(motion, t, X);
  const Point<2>     c = motion.die_center(t);
  const double       omega = (1.0 + R_G / R_D) * 0.3 + 0.75 * 0.2;
  const Tensor<1, 2> r = xc - c;
  const double       psi = std::atan2(c[1], c[0]);
  // Die centre velocity: a psi' e_perp - f' e_r, with a = R_G + R_D - f.
  const Tensor<1, 2> e_r = vec(std::cos(psi), std::sin(psi)),
                     e_p = vec(-std::sin(psi), std::cos(psi));
  const Tensor<1, 2> vc = (R_G + R_D - 0.15) * 0.3 * e_p - 0.1 * e_r;
  const Tensor<1, 2> expected = vc + omega * vec(-r[1], r[0]);
  EXPECT_NEAR(v[0], expected[0], 1e-7);
  EXPECT_NEAR(v[1], expected[1], 1e-7);
  // Without feed the tangential slip speed is exactly (1 - beta) R_D dtheta_s / dt.
  d.feed = {};
  const RollingMotion no_feed(d);
  const Point<2>      Xn = no_feed.pose(t).to_local(no_feed.pitch_point(t));
  const Tensor<1, 2>  vn = finite_difference_velocity(no_feed, t, Xn);
  EXPECT_NEAR(vn.norm(), 0.75 * R_D * 0.2, 1e-7);
  EXPECT_NEAR(vn * e_r, 0.0, 1e-7); // tangential
}

TEST(RollingMotion, InvalidDataThrows)
{
  RollingMotion::Data d;
  d.workpiece_radius = 10.0;
  d.die_radius = 0.0;
  EXPECT_THROW(RollingMotion{d}, ausroll::InputError);
  d.die_radius = 5.0;
  d.beta = 1.5;
  EXPECT_THROW(RollingMotion{d}, ausroll::InputError);
  d.beta = 1.0;
  d.direction = 0;
  EXPECT_THROW(RollingMotion{d}, ausroll::InputError);
}

// The motions come from the registry: `Motion/Type` lists the registered ones, and the entries of
// `Motion/Prescribed` give the motion built directly from the same functions, to the last bit (the
// same arithmetic); an entry of the flat `Motion` list of old files names its new subsection(s).
TEST(MotionRegistry, RegisteredMotionsAndTheirSubsections)
{
  using ausroll::contact::MotionRegistry;
  EXPECT_EQ(MotionRegistry::instance().names(),
            (std::vector<std::string>{"fixed", "prescribed", "rolling"}));

  dealii::ParameterHandler prm;
  prm.enter_subsection("Motion");
  prm.declare_entry("Type", "fixed", dealii::Patterns::Anything());
  MotionRegistry::instance().declare_subsections(prm);
  prm.leave_subsection();
  prm.parse_input_from_string("subsection Motion\nset Type = prescribed\nsubsection Prescribed\n"
                              "set Translation = 2 * t; -t\nset Rotation = 30 * t\n"
                              "set Pivot = 1, 2\nend\nend\n");
  prm.enter_subsection("Motion");
  const auto parameters
      = MotionRegistry::instance().parse("prescribed", prm, "Die/Motion/", "", "Type");
  prm.leave_subsection();
  const auto             motion = ausroll::contact::create_motion<2>(*parameters, "Die/Motion/");
  const PrescribedMotion direct([](const double t) { return vec(2. * t, -t); },
                                [](const double t) { return (M_PI / 180.) * (30. * t); },
                                Point<2>(1.0, 2.0));
  for (const double t : {0.0, 0.3, 1.7})
  {
    const Point<2> X(0.5, -1.5);
    EXPECT_EQ(motion->pose(t).to_global(X), direct.pose(t).to_global(X)) << t;
  }

  std::map<std::string, std::string> moved;
  ausroll::contact::add_moved_motion_entries("Contact/Die 0/Motion/", moved);
  EXPECT_EQ(moved.at("Contact/Die 0/Motion/Feed"), "`Contact/Die 0/Motion/Rolling/Feed`");
  EXPECT_EQ(moved.at("Contact/Die 0/Motion/Axis"),
            "`Contact/Die 0/Motion/Prescribed/Axis` or `Contact/Die 0/Motion/Rolling/Axis`");
}
