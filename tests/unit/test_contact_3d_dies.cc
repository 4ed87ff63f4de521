/**
 * @file test_contact_3d_dies.cc
 * RigidDie<3> as ContactOperator<3> sees it, read from `Contact/Die 0` texts: the projection of
 * points on spheres around a torus (round-faced disk die) and a finite cylinder placed by a 3D
 * pose (gap, closest point, normal exact: 1e-12), the planetary RollingMotion<3> about a tilted
 * workpiece axis (pitch point at rest, centre distance, axis kept: 1e-12 / 1e-6 for the
 * finite-difference velocity), the DiePose<3> round trip (1e-14), and the exit-2 messages for a
 * shape of the other dimension.
 */
#include <ausroll/contact/contact_parameters.h>
#include <ausroll/contact/motion/rolling.h>
#include <ausroll/contact/rigid_die.h>
#include <ausroll/core/exceptions.h>

#include "contact_test_utilities.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace dealii;
using namespace ausroll;
using ausroll::testing::parse_die;

namespace
{
  Tensor<1, 3> unit(const Tensor<1, 3> &v)
  {
    return v / v.norm();
  }
} // namespace

// A torus (R = 10, rho = 2) about the local z axis, its die frame rotated by 40 degrees about
// (1, 1, 1) and moved by (1, -2, 3) (prescribed motion at t = 1): for points x = c + (rho + g) m
// around the tube centre c of the meridian plane (m the unit vector from c, over the sphere of
// directions in that plane), the gap is g, the closest point c + rho m and the normal m.
TEST(Contact3dDies, TorusAndCylinderInAPose)
{
  const std::string motion = "subsection Motion\nset Type = prescribed\nsubsection Prescribed\n"
                             "set Translation = t; -2 * t; 3 * t\nset Rotation = 40 * t\n"
                             "set Axis = 1, 1, 1\nend\nend\n";
  const contact::RigidDie<3> torus(
      parse_die("set Shape = torus\nsubsection Torus\nset Major radius = 10\nset Minor radius = "
                "2\nend\n"
                + motion),
      0);
  const contact::DiePose<3> pose = torus.pose(1.);
  double                    worst = 0.;
  for (const double theta : {0.3, 2.0, -2.5})
    for (const double phi : {-1.2, 0.1, 0.9, 2.8})
      for (const double g : {-0.5, 0., 0.7})
      {
        const Tensor<1, 3> e_r({std::cos(theta), std::sin(theta), 0.});
        const Tensor<1, 3> m_local = std::cos(phi) * e_r + std::sin(phi) * Tensor<1, 3>({0, 0, 1});
        const Point<3>     c_local(10. * e_r);
        const Point<3>     x = pose.to_global(c_local + (2. + g) * m_local);
        const auto         p = torus.project(x, 1.);
        ASSERT_TRUE(p.valid);
        const Tensor<1, 3> m = pose.rotate_vector_to_global(m_local);
        worst = std::max({worst,
                          std::abs(p.gap - g),
                          (p.point - pose.to_global(c_local + 2. * m_local)).norm(),
                          (p.normal - m).norm(),
                          std::abs(p.tangents[0] * p.normal) + std::abs(p.tangents[1] * p.normal),
                          (cross_product_3d(p.tangents[0], p.tangents[1]) - p.normal).norm()});
      }
  EXPECT_LT(worst, 1e-12);

  // Finite cylinder (R = 5, width 4, axis y): x = axis point + (R + g) e_r inside the width.
  const contact::RigidDie<3> cylinder(
      parse_die("set Shape = cylinder\nset Search distance = 1\nsubsection Cylinder\n"
                "set Axis = 0, 1, 0\nset Radius = 5\n"
                "set Width = 4\nend\n"
                + motion),
      0);
  double worst_cylinder = 0.;
  for (const double alpha : {0.2, 1.7, -2.9})
    for (const double y : {-1.5, 0., 1.2})
      for (const double g : {-0.3, 0.4})
      {
        const Tensor<1, 3> e_r({std::sin(alpha), 0., std::cos(alpha)});
        const Point<3>     a(0., y, 0.);
        const auto         p = cylinder.project(pose.to_global(a + (5. + g) * e_r), 1.);
        ASSERT_TRUE(p.valid);
        worst_cylinder = std::max({worst_cylinder,
                                   std::abs(p.gap - g),
                                   (p.point - pose.to_global(a + 5. * e_r)).norm(),
                                   (p.normal - pose.rotate_vector_to_global(e_r)).norm()});
      }
  EXPECT_LT(worst_cylinder, 1e-12);
  // beyond the search distance (1): no projection
  EXPECT_FALSE(cylinder.project(pose.to_global(Point<3>(0., 0., 9.)), 1.).valid);
  std::printf("[ contact3d dies ] torus %.1e, cylinder %.1e\n", worst, worst_cylinder);
}

// Planetary rolling about the workpiece axis a = (0, 1, 1)/sqrt 2 through O_G: the die centre
// stays in the plane through O_G orthogonal to a at distance R_G + R_D, the die axis stays a, and
// the die point at the pitch point has zero velocity (pure rolling). The rolling motion is found
// by RigidDie::rolling_motion() (a virtual query of the motion).
TEST(Contact3dDies, RollingMotionAboutATiltedAxis)
{
  const contact::RigidDie<3> die(
      parse_die("set Shape = torus\nsubsection Torus\nset Major radius = 30\nset Minor radius = "
                "3\nend\nsubsection Motion\nset Type = rolling\nsubsection Rolling\n"
                "set Workpiece center = 1, 2, 3\nset Axis = 0, 1, 1\n"
                "set Workpiece rolling radius = 20\nset Die rolling radius = 30\n"
                "set Revolution angle = 30 * t\nend\nend\n"),
      0);
  const contact::RollingMotion<3> *rolling = die.rolling_motion();
  ASSERT_NE(rolling, nullptr);
  const Tensor<1, 3> a = unit(Tensor<1, 3>({0., 1., 1.}));
  const Point<3>     O(1., 2., 3.);
  for (const double t : {0., 0.4, 1.3})
  {
    const Point<3> c = rolling->die_center(t);
    EXPECT_NEAR((c - O) * a, 0., 1e-12);
    EXPECT_NEAR((c - O).norm(), 50., 1e-12);
    const contact::DiePose<3> pose = die.pose(t);
    EXPECT_NEAR((pose.axis() - a).norm(), 0., 1e-15);
    const Point<3>     pitch = rolling->pitch_point(t);
    const Point<3>     X = pose.to_local(pitch);
    const Tensor<1, 3> v = die.die_motion().velocity(t, X);
    const double       speed = 50. * (30. * M_PI / 180.);
    EXPECT_LT(v.norm(), 1e-6 * speed) << "t = " << t;
    // round trip of the pose
    const Point<3> Y(0.3, -7., 2.);
    EXPECT_LT((pose.to_local(pose.to_global(Y)) - Y).norm(), 1e-13);
  }
  // a fixed die has no rolling motion
  EXPECT_EQ(contact::RigidDie<3>(parse_die("set Shape = plane\n"), 0).rolling_motion(), nullptr);
}

// A 2D shape in a 3D run and a 3D shape in a 2D run: InputError naming Contact/Die 0/Shape.
TEST(Contact3dDies, ShapeOfTheOtherDimensionIsAnInputError)
{
  try
  {
    contact::RigidDie<3>(parse_die("set Shape = circle\n"), 0);
    FAIL() << "no error";
  }
  catch (const InputError &e)
  {
    EXPECT_NE(std::string(e.what()).find("Contact/Die 0/Shape"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("3D run"), std::string::npos) << e.what();
  }
  try
  {
    contact::RigidDie<2>(parse_die("set Shape = plane\n"), 0);
    FAIL() << "no error";
  }
  catch (const InputError &e)
  {
    EXPECT_NE(std::string(e.what()).find("Contact/Die 0/Shape"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("2D run"), std::string::npos) << e.what();
  }
  // three translation components in 3D
  EXPECT_THROW(
      contact::RigidDie<3>(parse_die("set Shape = plane\nsubsection Motion\nset Type = "
                                     "prescribed\nsubsection Prescribed\nset Translation = t; 0\n"
                                     "end\nend\n"),
                           0),
      InputError);
}
