/**
 * @file test_gear_tooth_mesh.cc
 * Unit tests of `Geometry/Type = gear tooth`: vertices of the refined mesh on the exact involute,
 * fillet and circles (FlankManifold and the other manifolds), boundary ids, cell quality.
 */
#include <ausroll/core/exceptions.h>
#include <ausroll/geometry/flank_manifold.h>
#include <ausroll/geometry/gear_tooth_mesh.h>
#include <ausroll/geometry/geometry_parameters.h>
#include <ausroll/geometry/workpiece.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_tools.h>

#include <gtest/gtest.h>

#include <cmath>
#include <map>

using namespace dealii;
using namespace ausroll::geometry;

namespace
{
  /** Thesis workpiece tooth (31 teeth, DP 8.5, PA 22 deg) with a root fillet of 0.75 mm. */
  GeometryParameters thesis_tooth(const unsigned int teeth, const double fillet)
  {
    GeometryParameters p;
    p.type = WorkpieceType::gear_tooth;
    p.gear_tooth.teeth = teeth;
    p.gear_tooth.root_fillet_radius = fillet;
    p.gear_tooth.tooth_axis_angle = 90.;
    return p;
  }

  /** Triangulation of @p p after @p refinements global refinements. */
  void build(GeometryParameters p, const unsigned int refinements, Triangulation<2> &tria)
  {
    p.global_refinements = refinements;
    create_workpiece(p, tria);
  }
} // namespace

// Chart manifold: push_forward(pull_back(x)) = x on the flank; derivative against differences.
TEST(FlankManifold, ChartAndGradient)
{
  const InvoluteGear g = GearToothParameters().gear();
  for (const FlankSide side : {FlankSide::positive, FlankSide::negative})
  {
    const FlankManifold flank(g, side, 0.7);
    for (const double r :
         {g.root_radius() + 0.1, g.base_radius() + 0.2, g.pitch_radius(), g.tip_radius()})
    {
      const Point<2> x = flank.push_forward(Point<1>(r));
      EXPECT_NEAR(flank.pull_back(x)[0], r, 1e-12 * r);
      EXPECT_NEAR(flank.angular_distance(x), 0., 1e-12 * r);
      const double       h = 1e-6;
      const Tensor<1, 2> fd
          = (flank.push_forward(Point<1>(r + h)) - flank.push_forward(Point<1>(r - h))) / (2. * h);
      const DerivativeForm<1, 1, 2> d = flank.push_forward_gradient(Point<1>(r));
      EXPECT_NEAR(d[0][0], fd[0], 1e-7);
      EXPECT_NEAR(d[1][0], fd[1], 1e-7);
    }
  }
}

// After 3 global refinements every vertex of a flank face lies on the involute (or its radial
// continuation) to 1e-10 relative; fillet vertices on the fillet circle, land vertices on the root
// and tip circles, inner arc on r_i.
TEST(GearToothMesh, RefinedBoundaryOnExactOutline)
{
  for (const auto &[teeth, fillet] : {std::pair{1u, 0.75}, {3u, 0.75}, {1u, 0.}, {2u, 0.3}})
  {
    const GeometryParameters p = thesis_tooth(teeth, fillet);
    Triangulation<2>         tria;
    build(p, 3, tria);
    const InvoluteGear                         g = p.gear_tooth.gear();
    const double                               ri = p.gear_tooth.inner_radius();
    const Point<2>                             c = g.tooth_geometry().fillet_center;
    std::map<types::boundary_id, unsigned int> n_faces;
    unsigned int                               n_flank = 0;
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
        {
          ++n_faces[face->boundary_id()];
          const types::manifold_id id = face->manifold_id();
          for (unsigned int v = 0; v < 2; ++v)
          {
            const Point<2> x = face->vertex(v);
            if (id >= 10 && id != numbers::flat_manifold_id)
            {
              const unsigned int k = (id - 10) / 10, piece = (id - 10) % 10;
              const double       axis = p.gear_tooth.axis_angle(k);
              const FlankSide    side = piece % 2 == 0 ? FlankSide::positive : FlankSide::negative;
              if (piece < 2)
              {
                EXPECT_LT(std::abs(FlankManifold(g, side, axis).angular_distance(x)),
                          1e-10 * x.norm());
                ++n_flank;
              }
              else
              {
                const Point<2> cs(c[0], side == FlankSide::positive ? c[1] : -c[1]);
                const Point<2> ca(std::cos(axis) * cs[0] - std::sin(axis) * cs[1],
                                  std::sin(axis) * cs[0] + std::cos(axis) * cs[1]);
                EXPECT_NEAR(x.distance(ca), fillet, 1e-10 * x.norm())
                    << "teeth " << teeth << " fillet " << fillet << " id " << id;
              }
            }
            else if (id == 1)
            {
              const double r = x.norm();
              const double d = std::min(
                  {std::abs(r - ri), std::abs(r - g.root_radius()), std::abs(r - g.tip_radius())});
              EXPECT_LT(d, 1e-10 * r);
            }
          }
        }
    EXPECT_GT(n_flank, 2u * teeth * 2u * 8u);
    EXPECT_EQ(n_faces.size(), 3u);
    // Tooth outline faces per tooth; inner arc spans the whole sector.
    EXPECT_GT(n_faces[0], 0u);
    EXPECT_GT(n_faces[1], 0u);
    EXPECT_GT(n_faces[2], 0u);
    // Area: between the analytic sector of the rim and the sector up to the tip circle.
    const double area = GridTools::volume(tria);
    const double phi = 2. * M_PI * teeth / g.n_teeth();
    EXPECT_GT(area, 0.5 * phi * (g.root_radius() * g.root_radius() - ri * ri));
    EXPECT_LT(area, 0.5 * phi * (g.tip_radius() * g.tip_radius() - ri * ri));
  }
}

// Tooth area against the analytic one: the area of one tooth sector above r_i is
// int_{-pi/z}^{pi/z} ... computed here as the rim sector plus twice the integral of r theta_h(r) dr
// over the tooth (sharp root, fillet 0); the refined mesh with a second-order mapping is exact to
// a small discretisation error.
TEST(GearToothMesh, AreaMatchesAnalyticTooth)
{
  const GeometryParameters p = thesis_tooth(1, 0.);
  Triangulation<2>         tria;
  build(p, 4, tria);
  const InvoluteGear g = p.gear_tooth.gear();
  const double       ri = p.gear_tooth.inner_radius(), rr = g.root_radius(), rt = g.tip_radius();
  // Rim: full sector up to rr; tooth: 2 int_rr^rt r theta_h(r) dr (midpoint rule, fine).
  double             tooth = 0.;
  const unsigned int n = 200000;
  for (unsigned int i = 0; i < n; ++i)
  {
    const double r = rr + (rt - rr) * (i + 0.5) / n;
    tooth += 2. * r * g.half_thickness_angle(r) * (rt - rr) / n;
  }
  const double exact = M_PI / g.n_teeth() * (rr * rr - ri * ri) + tooth;
  MappingQ<2>  mapping(2);
  FE_Q<2>      fe(1);
  QGauss<2>    quad(3);
  FEValues<2>  fev(mapping, fe, quad, update_JxW_values);
  double       area = 0.;
  for (const auto &cell : tria.active_cell_iterators())
  {
    fev.reinit(cell);
    for (unsigned int q = 0; q < quad.size(); ++q)
      area += fev.JxW(q);
  }
  EXPECT_NEAR(area, exact, 1e-5 * exact);
}

// Cells are well shaped after refinement: positive Jacobian at every quadrature point and in
// every vertex corner, aspect ratio (longest / shortest edge) below 8.
TEST(GearToothMesh, CellQuality)
{
  for (const double fillet : {0.75, 0., 0.3})
  {
    Triangulation<2> tria;
    build(thesis_tooth(2, fillet), 2, tria);
    MappingQ<2> mapping(2);
    FE_Q<2>     fe(1);
    QGauss<2>   quad(3);
    FEValues<2> fev(mapping, fe, quad, update_jacobians);
    double      worst_aspect = 0.;
    for (const auto &cell : tria.active_cell_iterators())
    {
      fev.reinit(cell);
      for (unsigned int q = 0; q < quad.size(); ++q)
        EXPECT_GT(determinant(Tensor<2, 2>(fev.jacobian(q))), 0.);
      // Corner Jacobians of the bilinear cell: cross product of the two edges at each vertex.
      const unsigned int next[4] = {1, 3, 0, 2}; // counter-clockwise neighbour (lexicographic)
      const unsigned int prev[4] = {2, 0, 3, 1};
      double             longest = 0., shortest = 1e300;
      for (unsigned int v = 0; v < 4; ++v)
      {
        const Tensor<1, 2> a = cell->vertex(next[v]) - cell->vertex(v);
        const Tensor<1, 2> b = cell->vertex(prev[v]) - cell->vertex(v);
        EXPECT_GT(a[0] * b[1] - a[1] * b[0], 0.);
        longest = std::max(longest, a.norm());
        shortest = std::min(shortest, a.norm());
      }
      worst_aspect = std::max(worst_aspect, longest / shortest);
    }
    EXPECT_LT(worst_aspect, 8.) << "fillet " << fillet;
  }
}

// Fix root: the side cuts get the inner arc's id.
TEST(GearToothMesh, FixRootMergesSideCutsIntoInnerArc)
{
  GeometryParameters p = thesis_tooth(1, 0.75);
  p.gear_tooth.fix_root = true;
  Triangulation<2> tria;
  build(p, 1, tria);
  for (const auto &face : tria.active_face_iterators())
    if (face->at_boundary())
      EXPECT_NE(face->boundary_id(), gear_tooth_ids::side_cuts);
}

TEST(GearToothMesh, BadInputThrows)
{
  GearToothParameters p;
  p.rim_thickness = 50.; // more than the root radius 42.6 mm
  EXPECT_THROW(p.inner_radius(), ausroll::InputError);
  GearToothParameters q;
  q.root_fillet_radius = 3.; // does not fit into the tooth space
  EXPECT_THROW(q.gear(), ausroll::InputError);
  GearToothParameters r;
  r.teeth = 40;
  EXPECT_THROW(r.gear(), ausroll::InputError);
}
