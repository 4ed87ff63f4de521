/**
 * @file test_boundary_depth.cc
 * Unit tests of geometry::BoundaryDepth (the depth below the initial surface of the carburized
 * case) against closed forms: the circles of a ring (R - r), the involute flank and the root
 * fillet of the gear tooth (points placed along the involute's own normal, which is the closest
 * point: the normal of an involute is tangent to the base circle, its centre of curvature), the
 * mantle of a quarter cylinder and the flank of the extruded tooth in 3D, and the input error.
 *
 * Tolerance 1e-9 of the outline's size everywhere: BoundaryDepth states below 1e-12 for a foot
 * inside a smooth face (Brent's minimum of the squared distance, quadratic in the face parameter
 * found to 1.5e-8) and round-off at a corner; the references are closed forms evaluated to
 * round-off (the involute point and normal of InvoluteGear). The coarse faces are far from the
 * curves (8 cells around the ring: a chord lies 3.8 mm inside the circle of radius 50), so the
 * distance to the straight faces would fail by orders of magnitude.
 *
 * Also the carbon profile of `Phases/Carbon content` in the depth (expression and table) and the
 * memoised functions of the carbon content (bit-identical to evaluating the expression).
 */
#include <ausroll/core/exceptions.h>
#include <ausroll/geometry/boundary_depth.h>
#include <ausroll/geometry/gear_tooth_mesh.h>
#include <ausroll/geometry/geometry_parameters.h>
#include <ausroll/geometry/workpiece.h>
#include <ausroll/material/carbon_function.h>
#include <ausroll/material/carbon_profile.h>

#include <deal.II/grid/tria.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <random>

using namespace dealii;
using namespace ausroll;
using namespace ausroll::geometry;

namespace
{
  /** @p p rotated by @p angle about the origin (x-y plane). */
  Point<2> rotated(const Point<2> &p, const double angle)
  {
    return Point<2>(std::cos(angle) * p[0] - std::sin(angle) * p[1],
                    std::sin(angle) * p[0] + std::cos(angle) * p[1]);
  }

  /** The thesis tooth (31 teeth, DP 8.5, 22 degrees) with a 0.75 mm fillet, 2D or extruded. */
  GeometryParameters tooth(const bool extruded)
  {
    GeometryParameters p;
    p.type = extruded ? WorkpieceType::extruded_gear_tooth : WorkpieceType::gear_tooth;
    p.gear_tooth.teeth = 1;
    p.gear_tooth.root_fillet_radius = 0.75;
    p.gear_face_width = 6.;
    p.gear_layers = 2;
    p.global_refinements = 1; // the depth uses the coarse cells whatever the refinement
    return p;
  }

  /** The tooth of tooth() built, and the depth below its outline (boundary id 0). */
  template <int dim>
  struct ToothDepth
  {
    ToothDepth()
        : p(tooth(dim == 3))
        , gear(p.gear_tooth.gear())
        , axis(p.gear_tooth.axis_angle(0))
    {
      create_workpiece(p, tria);
      depth = std::make_unique<BoundaryDepth<dim>>(
          tria, std::vector<unsigned int>{gear_tooth_ids::outline}, "Phases/Case boundaries");
    }
    GeometryParameters                  p;
    Triangulation<dim>                  tria;
    InvoluteGear                        gear;
    double                              axis; ///< polar angle of the tooth axis
    std::unique_ptr<BoundaryDepth<dim>> depth;
  };

  /**
   * Points inside the tooth at depth t below the positive flank (tooth frame): the flank point
   * at radius r moved by t against the flank's outward normal, r from the flank start + 1 mm to
   * the tip - 1.2 mm and t <= 0.5 mm (so that the tip land, the fillet and the other flank are
   * farther than t, and t is below the radius of curvature sqrt(r^2 - r_b^2) > 5 mm).
   */
  std::vector<std::pair<Point<2>, double>> flank_points(const InvoluteGear &gear)
  {
    std::vector<std::pair<Point<2>, double>> points;
    const double r_0 = gear.tooth_geometry().flank_start_radius + 1., r_1 = gear.tip_radius() - 1.2;
    for (unsigned int i = 0; i <= 10; ++i)
      for (const double t : {0., 0.01, 0.1, 0.3, 0.5})
      {
        const double r = r_0 + (r_1 - r_0) * i / 10.;
        points.emplace_back(gear.flank_point(r, FlankSide::positive)
                                - t * gear.flank_normal(r, FlankSide::positive),
                            t);
      }
    return points;
  }
} // namespace

// The ring 20 <= r <= 50 with 8 coarse cells around: the depth below the outer circle is
// 50 - r, below both circles min(50 - r, r - 20), at random points of the annulus; 1e-9 of 50.
TEST(BoundaryDepth, RingCircles)
{
  GeometryParameters p;
  p.type = WorkpieceType::ring;
  p.ring_inner_radius = 20.;
  p.ring_outer_radius = 50.;
  p.ring_cells_around = 8;
  p.ring_cells_radially = 2;
  p.global_refinements = 1;
  Triangulation<2> tria;
  create_workpiece(p, tria);
  const BoundaryDepth<2> outer(tria, {1}, "Phases/Case boundaries");
  const BoundaryDepth<2> both(tria, {0, 1}, "Phases/Case boundaries");
  EXPECT_EQ(outer.n_faces(), 8u);
  std::mt19937                           random(37);
  std::uniform_real_distribution<double> radius(20., 50.), angle(0., 2. * M_PI);
  double                                 error = 0.;
  for (unsigned int k = 0; k < 400; ++k)
  {
    const double   r = radius(random), phi = angle(random);
    const Point<2> x(r * std::cos(phi), r * std::sin(phi));
    error = std::max(error, std::abs(outer.depth(x) - (50. - r)));
    error = std::max(error, std::abs(both.depth(x) - std::min(50. - r, r - 20.)));
  }
  // at a coarse vertex and in the middle of a coarse face (where the chord is 3.8 mm inside)
  error = std::max(error, std::abs(outer.depth(Point<2>(45., 0.)) - 5.));
  error = std::max(error, std::abs(outer.depth(rotated(Point<2>(45., 0.), M_PI / 8.)) - 5.));
  EXPECT_LT(error, 1e-9 * 50.);
}

// The gear tooth's outline (boundary id 0): points along the involute's normal at depth t below
// the flank, and points on the normal of the root fillet, t below it (the fillet is concave:
// the depth is |x - c| - rho); 1e-9 of the tip radius.
TEST(BoundaryDepth, GearToothFlankAndFillet)
{
  const ToothDepth<2> tooth;
  const InvoluteGear &gear = tooth.gear;
  double              flank = 0.;
  for (const auto &[x, t] : flank_points(gear))
    flank = std::max(flank, std::abs(tooth.depth->depth(rotated(x, tooth.axis)) - t));
  EXPECT_LT(flank, 1e-9 * gear.tip_radius());

  // the fillet of the positive flank: centre c, radius rho, the arc between its tangency with
  // the root circle and with the flank; points at rho + t from c on the arc's middle normal
  const ToothGeometry &g = gear.tooth_geometry();
  const double         rho = gear.root_fillet_radius();
  const Point<2>       c = g.fillet_center;
  const Point<2>       on_root = Point<2>() + c * (gear.root_radius() / c.norm());
  const Point<2>       on_flank = gear.flank_point(g.flank_start_radius, FlankSide::positive);
  const Tensor<1, 2>   middle = (on_root - c) / rho + (on_flank - c) / rho;
  double               fillet = 0.;
  for (const double t : {0., 0.05, 0.2, 0.4})
  {
    const Point<2> x = c + (rho + t) * middle / middle.norm();
    fillet = std::max(fillet, std::abs(tooth.depth->depth(rotated(x, tooth.axis)) - t));
  }
  EXPECT_LT(fillet, 1e-9 * gear.tip_radius());
}

// 3D: the quarter cylinder R = 2, L = 3 (mantle id 2): depth R - |(x, y)| below the mantle,
// min(R - |(x, y)|, L - z) below the mantle and the end z = L (id 4); 1e-9 of R.
TEST(BoundaryDepth, QuarterCylinderMantle)
{
  GeometryParameters p;
  p.type = WorkpieceType::quarter_cylinder;
  p.cylinder_radius = 2.;
  p.cylinder_length = 3.;
  p.cylinder_layers = 2;
  p.global_refinements = 1;
  Triangulation<3> tria;
  create_workpiece(p, tria);
  namespace ids = boundary_ids_3d::quarter_cylinder;
  const BoundaryDepth<3> mantle(tria, {ids::mantle}, "Phases/Case boundaries");
  const BoundaryDepth<3> mantle_top(tria, {ids::mantle, ids::top}, "Phases/Case boundaries");
  std::mt19937           random(7);
  std::uniform_real_distribution<double> radius(0., 2.), angle(0., M_PI / 2.), height(0., 3.);
  double                                 error = 0.;
  for (unsigned int k = 0; k < 100; ++k)
  {
    const double   r = radius(random), phi = angle(random), z = height(random);
    const Point<3> x(r * std::cos(phi), r * std::sin(phi), z);
    error = std::max(error, std::abs(mantle.depth(x) - (2. - r)));
    error = std::max(error, std::abs(mantle_top.depth(x) - std::min(2. - r, 3. - z)));
  }
  EXPECT_LT(error, 1e-9 * 2.);
}

// nearest(): the foot and the inward normal on the quarter cylinder's mantle, exact: foot
// (R cos phi, R sin phi, z), normal -(cos phi, sin phi, 0). Foot to 1e-6 of R (Brent locates
// the face parameter to 1.5e-8, the alternating sweeps in 3D a little worse), normal to 1e-6
// (central differences of the face points with a parameter step of 1e-5).
TEST(BoundaryDepth, NearestFootAndNormalOnTheMantle)
{
  GeometryParameters p;
  p.type = WorkpieceType::quarter_cylinder;
  p.cylinder_radius = 2.;
  p.cylinder_length = 3.;
  p.cylinder_layers = 2;
  p.global_refinements = 1;
  Triangulation<3> tria;
  create_workpiece(p, tria);
  const BoundaryDepth<3> mantle(
      tria, {boundary_ids_3d::quarter_cylinder::mantle}, "Postprocess/Depth probe boundaries");
  std::mt19937                           random(11);
  std::uniform_real_distribution<double> radius(0.5, 2.2), angle(0.05, M_PI / 2. - 0.05),
      height(0., 3.);
  double foot_error = 0., normal_error = 0.;
  for (unsigned int k = 0; k < 50; ++k)
  {
    const double   r = radius(random), phi = angle(random), z = height(random);
    const auto     foot = mantle.nearest(Point<3>(r * std::cos(phi), r * std::sin(phi), z));
    const Point<3> exact(2. * std::cos(phi), 2. * std::sin(phi), z);
    Tensor<1, 3>   inward;
    inward[0] = -std::cos(phi);
    inward[1] = -std::sin(phi);
    foot_error = std::max(foot_error, foot.point.distance(exact));
    normal_error = std::max(normal_error, (foot.inward_normal - inward).norm());
    EXPECT_NEAR(foot.distance, std::abs(2. - r), 1e-9 * 2.);
  }
  EXPECT_LT(foot_error, 1e-6 * 2.);
  EXPECT_LT(normal_error, 1e-6);
}

// 3D: the flank of the extruded tooth (lateral id 0) at two heights: the 2D flank points; the
// symmetry face z = 0 and the face end z = 3 are not in the outline, so the depth is the 2D one.
TEST(BoundaryDepth, ExtrudedToothFlank)
{
  const ToothDepth<3> tooth;
  double              error = 0.;
  for (const double z : {0.4, 2.9})
    for (const auto &[x, t] : flank_points(tooth.gear))
    {
      const Point<2> y = rotated(x, tooth.axis);
      error = std::max(error, std::abs(tooth.depth->depth(Point<3>(y[0], y[1], z)) - t));
    }
  EXPECT_LT(error, 1e-9 * tooth.gear.tip_radius());
}

// An id without a boundary face is an InputError naming the entry.
TEST(BoundaryDepth, MissingIdNamesTheEntry)
{
  GeometryParameters p;
  p.type = WorkpieceType::ring;
  Triangulation<2> tria;
  create_workpiece(p, tria);
  try
  {
    const BoundaryDepth<2> depth(tria, {7}, "Phases/Case boundaries");
    FAIL() << "no error for boundary id 7";
  }
  catch (const InputError &e)
  {
    EXPECT_NE(std::string(e.what()).find("Phases/Case boundaries"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("id 7"), std::string::npos);
  }
}

namespace
{
  /** The rectangle 10 x 2 (ids 0 x = 0, 1 x = 10, 2 y = 0, 3 y = 2), 4 x 2 coarse cells. */
  void rectangle(Triangulation<2> &tria)
  {
    GeometryParameters p;
    p.type = WorkpieceType::rectangle;
    p.lower_left = Point<2>(0., 0.);
    p.upper_right = Point<2>(10., 2.);
    p.rectangle_cells = {4, 2};
    create_workpiece(p, tria);
  }
} // namespace

// The profile as an expression of depth (below y = 2) and of x, and as a table file of C against
// depth (linear between the rows, constant beyond): against the closed forms to round-off
// (1e-14: one erfc or one linear interpolation).
TEST(CarbonProfile, ExpressionAndTableInDepth)
{
  using ausroll::material::CarbonProfile;
  Triangulation<2> tria;
  rectangle(tria);
  const std::string erfc_profile = "0.2 + 0.7 * erfc(depth / 0.6) + 0.001 * x";
  EXPECT_TRUE(CarbonProfile<2>::uses_depth(erfc_profile));
  EXPECT_FALSE(CarbonProfile<2>::uses_depth("0.2 + 0.01 * depthx"));
  const CarbonProfile<2> expression(erfc_profile, tria, {3}, "");
  const CarbonProfile<2> uniform("0.8", tria, {}, "");
  EXPECT_EQ(uniform.depth(), nullptr); // no depth computed when the profile does not use it
  {
    std::ofstream table("carbon_case_table.csv");
    table << "depth, carbon\n0, 0.9\n0.5, 0.6\n1.5, 0.2\n";
  }
  const CarbonProfile<2> table("file: carbon_case_table.csv", tria, {3}, ".");
  std::remove("carbon_case_table.csv");
  double error = 0.;
  for (const double y : {0., 0.3, 1.2, 1.75, 2.})
    for (const double x : {0.5, 7.})
    {
      const double d = 2. - y;
      error = std::max(error,
                       std::abs(expression.value(Point<2>(x, y))
                                - (0.2 + 0.7 * std::erfc(d / 0.6) + 0.001 * x)));
      const double C = d <= 0.5 ? 0.9 - 0.6 * d : d <= 1.5 ? 0.6 - 0.4 * (d - 0.5) : 0.2;
      error = std::max(error, std::abs(table.value(Point<2>(x, y)) - C));
      EXPECT_EQ(uniform.value(Point<2>(x, y)), 0.8);
    }
  EXPECT_LT(error, 1e-14);
}

// The memo returns the expression's value bit for bit, for two functions at the same carbon
// contents (keyed apart) and for more carbon values than the table has entries.
TEST(CarbonFunction, MemoIsBitIdentical)
{
  using ausroll::material::CarbonFunction;
  const CarbonFunction ms("539 - 423*C - 89.665", "Ms"), dv("4.64 - 0.53*C", "dV");
  for (unsigned int pass = 0; pass < 2; ++pass)
    for (unsigned int k = 0; k < 3 * CarbonFunction::slots; ++k)
    {
      const double C = 2.1 * k / (3. * CarbonFunction::slots);
      ASSERT_EQ(ms.value(C), ms.evaluate(C));
      ASSERT_EQ(dv.value(C), dv.evaluate(C));
    }
}
