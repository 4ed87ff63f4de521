/**
 * @file test_workpiece_3d.cc
 * Unit tests of the three-dimensional workpieces of `Geometry/Type` (block, quarter cylinder,
 * thick ring, extruded gear tooth): volume and area of every boundary id against the analytic
 * values, vertices of refined meshes on the exact cylinders and involute flanks, the mid-plane of
 * the extruded tooth against the 2D tooth mesh, and the input errors (3D shape in a 2D run and
 * vice versa, bad sizes).
 */
#include <ausroll/core/exceptions.h>
#include <ausroll/geometry/flank_manifold.h>
#include <ausroll/geometry/gear_tooth_mesh.h>
#include <ausroll/geometry/geometry_parameters.h>
#include <ausroll/geometry/workpiece.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <string>

using namespace dealii;
using namespace ausroll;
using namespace ausroll::geometry;

namespace
{
  /** Volume and the area of every boundary id of @p tria with a mapping of degree @p degree. */
  template <int dim>
  std::pair<double, std::map<unsigned int, double>> measure(const Triangulation<dim> &tria,
                                                            const unsigned int        degree)
  {
    const MappingQ<dim>            mapping(degree);
    const FE_Nothing<dim>          fe;
    const QGauss<dim>              quadrature(degree + 2);
    const QGauss<dim - 1>          face_quadrature(degree + 2);
    FEValues<dim>                  fe_values(mapping, fe, quadrature, update_JxW_values);
    FEFaceValues<dim>              fe_face(mapping, fe, face_quadrature, update_JxW_values);
    double                         volume = 0.;
    std::map<unsigned int, double> area;
    for (const auto &cell : tria.active_cell_iterators())
    {
      fe_values.reinit(cell);
      for (unsigned int q = 0; q < quadrature.size(); ++q)
        volume += fe_values.JxW(q);
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary())
        {
          fe_face.reinit(cell, f);
          for (unsigned int q = 0; q < face_quadrature.size(); ++q)
            area[cell->face(f)->boundary_id()] += fe_face.JxW(q);
        }
    }
    return {volume, area};
  }

  /** The parameters of subsection Geometry after reading @p text (entries inside Geometry). */
  GeometryParameters parse(const std::string &text)
  {
    ParameterHandler prm;
    GeometryParameters::declare_parameters(prm);
    prm.parse_input_from_string("subsection Geometry\n" + text + "\nend\n");
    GeometryParameters p;
    p.parse_parameters(prm, "");
    return p;
  }

  /** Largest |value - expected| / scale over the ids of @p expected; every id present. */
  double area_error(const std::map<unsigned int, double> &area,
                    const std::map<unsigned int, double> &expected,
                    const double                          scale)
  {
    EXPECT_EQ(area.size(), expected.size()) << "boundary ids other than the documented ones";
    double error = 0.;
    for (const auto &[id, value] : expected)
    {
      EXPECT_EQ(area.count(id), 1u) << "boundary id " << id << " missing";
      if (area.count(id))
        error = std::max(error, std::abs(area.at(id) - value) / scale);
    }
    return error;
  }
} // namespace

// Block: trilinear cells of a box are exact: volume and the six face areas to round-off (1e-12).
TEST(Workpiece3d, BlockVolumeAndFaceAreas)
{
  const GeometryParameters p = parse("set Type = block\nset Global refinements = 1\n"
                                     "subsection Block\nset Lower corner = 0, 0, 0\n"
                                     "set Upper corner = 2, 3, 4\nset Cells = 2, 1, 3\nend");
  Triangulation<3>         tria;
  create_workpiece(p, tria);
  EXPECT_EQ(tria.n_active_cells(), 6u * 8u);
  const auto [volume, area] = measure(tria, 1);
  EXPECT_NEAR(volume, 24., 1e-12 * 24.);
  namespace ids = boundary_ids_3d::block;
  EXPECT_LT(area_error(area,
                       {{ids::x_min, 12.},
                        {ids::x_max, 12.},
                        {ids::y_min, 8.},
                        {ids::y_max, 8.},
                        {ids::z_min, 6.},
                        {ids::z_max, 6.}},
                       24.),
            1e-12);
}

// Quarter cylinder R = 2, L = 3 after 2 refinements (3 x 2 coarse cells -> 384): every vertex of
// the mantle on the cylinder to 1e-10 R (the cylindrical manifold places new points exactly;
// 1e-10 allows the chart round-off). Volume and areas with a mapping of degree 3 whose support
// points lie on the manifolds: geometric error O(h^4) relative to the arc length of the cells (an
// angle of about pi/8 after 2 refinements): measured 8e-10, tolerance 1e-8 relative.
TEST(Workpiece3d, QuarterCylinderOnCylinderVolumeAndAreas)
{
  const double             R = 2., L = 3.;
  const GeometryParameters p = parse("set Type = quarter cylinder\nset Global refinements = 2\n"
                                     "subsection Quarter cylinder\nset Radius = 2\n"
                                     "set Length = 3\nset Layers = 2\nend");
  Triangulation<3>         tria;
  create_workpiece(p, tria);
  EXPECT_EQ(tria.n_active_cells(), 6u * 64u);
  namespace ids = boundary_ids_3d::quarter_cylinder;
  double distance = 0.;
  for (const auto &cell : tria.active_cell_iterators())
    for (const auto &face : cell->face_iterators())
      if (face->at_boundary() && face->boundary_id() == ids::mantle)
        for (const unsigned int v : face->vertex_indices())
          distance = std::max(distance,
                              std::abs(std::hypot(face->vertex(v)[0], face->vertex(v)[1]) - R));
  std::printf("[ geo3d ] quarter cylinder: max |r - R| on the mantle = %.1e\n", distance);
  EXPECT_LT(distance, 1e-10 * R);

  const auto [volume, area] = measure(tria, 3);
  const double exact = M_PI * R * R / 4. * L;
  std::printf("[ geo3d ] quarter cylinder: volume error %.1e\n", std::abs(volume - exact) / exact);
  EXPECT_NEAR(volume, exact, 1e-8 * exact);
  EXPECT_LT(area_error(area,
                       {{ids::symmetry_x, R * L},
                        {ids::symmetry_y, R * L},
                        {ids::mantle, M_PI * R / 2. * L},
                        {ids::bottom, M_PI * R * R / 4.},
                        {ids::top, M_PI * R * R / 4.}},
                       M_PI * R / 2. * L),
            1e-8);
}

// Thick ring (bore 1, rim 2, thickness 1.5, half 0.75 meshed) after 2 refinements: bore and rim
// vertices on their circles to 1e-10 (cylindrical manifold on every cell); volume and areas with a
// degree-2 mapping on the manifold: the radial direction is straight, the angular one O(h^3)
// with 96 cells around (measured 4e-8): tolerance 1e-6 relative.
TEST(Workpiece3d, ThickRingOnCirclesVolumeAndAreas)
{
  const double             a = 1., b = 2., h = 0.75;
  const GeometryParameters p = parse("set Type = thick ring\nset Global refinements = 2\n"
                                     "subsection Ring\nset Center = 0.5, -0.25\n"
                                     "set Inner radius = 1\nset Outer radius = 2\n"
                                     "set Cells around = 24\nset Cells radially = 2\nend\n"
                                     "subsection Thick ring\nset Thickness = 1.5\n"
                                     "set Layers = 1\nend");
  Triangulation<3>         tria;
  create_workpiece(p, tria);
  namespace ids = boundary_ids_3d::thick_ring;
  const Point<3> c(0.5, -0.25, 0.);
  double         distance = 0.;
  for (const auto &cell : tria.active_cell_iterators())
    for (const auto &face : cell->face_iterators())
      if (face->at_boundary()
          && (face->boundary_id() == ids::bore || face->boundary_id() == ids::rim))
        for (const unsigned int v : face->vertex_indices())
        {
          const Tensor<1, 3> d = face->vertex(v) - c;
          const double       r = face->boundary_id() == ids::bore ? a : b;
          distance = std::max(distance, std::abs(std::hypot(d[0], d[1]) - r));
          EXPECT_GE(face->vertex(v)[2], -1e-12);
          EXPECT_LE(face->vertex(v)[2], h + 1e-12);
        }
  std::printf("[ geo3d ] thick ring: max distance of bore/rim vertices = %.1e\n", distance);
  EXPECT_LT(distance, 1e-10);

  const auto [volume, area] = measure(tria, 2);
  const double annulus = M_PI * (b * b - a * a);
  std::printf("[ geo3d ] thick ring: volume error %.1e\n",
              std::abs(volume - annulus * h) / (annulus * h));
  EXPECT_NEAR(volume, annulus * h, 1e-6 * annulus * h);
  EXPECT_LT(area_error(area,
                       {{ids::bore, 2. * M_PI * a * h},
                        {ids::rim, 2. * M_PI * b * h},
                        {ids::side, annulus},
                        {ids::symmetry, annulus}},
                       annulus),
            1e-6);
}

// Thick ring sector (Ring/Sector angle = 60, centre off the origin) after 2 refinements: the
// volume, bore, rim, side, symmetry and the two cut faces (ids 4, 5) against the analytic values
// (1e-6: Q2 mapping of the circles), the cut faces planar through the centre at 0 and 60 degrees.
TEST(Workpiece3d, ThickRingSectorVolumeAndCutFaces)
{
  const double             a = 1., b = 2., h = 0.75, phi = M_PI / 3.;
  const GeometryParameters p = parse("set Type = thick ring\nset Global refinements = 2\n"
                                     "subsection Ring\nset Center = 0.5, -0.25\n"
                                     "set Inner radius = 1\nset Outer radius = 2\n"
                                     "set Cells around = 4\nset Cells radially = 2\n"
                                     "set Sector angle = 60\nend\n"
                                     "subsection Thick ring\nset Thickness = 1.5\n"
                                     "set Layers = 1\nend");
  Triangulation<3>         tria;
  create_workpiece(p, tria);
  namespace ids = boundary_ids_3d::thick_ring;
  const Tensor<1, 3> c({0.5, -0.25, 0.});
  const Tensor<1, 3> n_end({-std::sin(phi), std::cos(phi), 0.});
  double             off_plane = 0.;
  for (const auto &cell : tria.active_cell_iterators())
    for (const auto &face : cell->face_iterators())
      if (face->at_boundary()
          && (face->boundary_id() == ids::cut_start || face->boundary_id() == ids::cut_end))
        for (const unsigned int v : face->vertex_indices())
        {
          const Tensor<1, 3> d = face->vertex(v) - c;
          off_plane = std::max(off_plane,
                               std::abs(face->boundary_id() == ids::cut_start ? d[1] : d * n_end));
        }
  EXPECT_LT(off_plane, 1e-12);
  const auto [volume, area] = measure(tria, 2);
  const double section = 0.5 * phi * (b * b - a * a);
  EXPECT_NEAR(volume, section * h, 1e-6 * section * h);
  EXPECT_LT(area_error(area,
                       {{ids::bore, phi * a * h},
                        {ids::rim, phi * b * h},
                        {ids::side, section},
                        {ids::symmetry, section},
                        {ids::cut_start, (b - a) * h},
                        {ids::cut_end, (b - a) * h}},
                       section),
            1e-6);
}

namespace
{
  /** The thesis tooth with a 0.75 mm root fillet, @p teeth teeth, meshed in 2D or extruded. */
  GeometryParameters tooth(const unsigned int teeth, const bool extruded)
  {
    GeometryParameters p;
    p.type = extruded ? WorkpieceType::extruded_gear_tooth : WorkpieceType::gear_tooth;
    p.gear_tooth.teeth = teeth;
    p.gear_tooth.root_fillet_radius = 0.75;
    p.gear_face_width = 6.;
    p.gear_layers = 2;
    p.global_refinements = 2;
    return p;
  }
} // namespace

// Extruded gear tooth (thesis tooth, 2 teeth, half face width 3 mm) after 2 refinements: every
// vertex of a flank face on the involute of its tooth (angular distance), of a fillet face on the
// fillet cylinder, of a land face on the tip or root cylinder, of the inner arc on r_i, to 1e-10
// of the tip radius (the manifolds place new points exactly; round-off of the charts).
TEST(Workpiece3d, ExtrudedGearToothOnFlanksAfterRefinement)
{
  const GeometryParameters p = tooth(2, true);
  Triangulation<3>         tria;
  create_workpiece(p, tria);
  const InvoluteGear g = p.gear_tooth.gear();
  const double       rt = g.tip_radius(), rr = g.root_radius(), ri = p.gear_tooth.inner_radius();
  const Point<2>     fc = g.tooth_geometry().fillet_center;
  double             flank = 0., fillet = 0., circle = 0.;
  unsigned int       n_flank = 0, n_fillet = 0;
  for (const auto &face : tria.active_face_iterators())
    if (face->at_boundary())
    {
      const types::manifold_id m = face->manifold_id();
      for (const unsigned int v : face->vertex_indices())
      {
        const Point<3> x = face->vertex(v);
        if (m >= 10 && m != numbers::flat_manifold_id)
        {
          const unsigned int k = (m - 10) / 10, j = (m - 10) % 10;
          const double       axis = p.gear_tooth.axis_angle(k);
          if (j < 2)
          {
            const ExtrudedFlankManifold manifold(
                g, j == 0 ? FlankSide::positive : FlankSide::negative, axis);
            flank = std::max(flank, std::abs(manifold.angular_distance(x)));
            ++n_flank;
          }
          else
          {
            const double   c = std::cos(axis), s = std::sin(axis), sy = j == 2 ? 1. : -1.;
            const Point<2> f(c * fc[0] - s * sy * fc[1], s * fc[0] + c * sy * fc[1]);
            fillet = std::max(
                fillet, std::abs(std::hypot(x[0] - f[0], x[1] - f[1]) - g.root_fillet_radius()));
            ++n_fillet;
          }
        }
        else if (m == 1)
        {
          const double r = std::hypot(x[0], x[1]);
          circle
              = std::max(circle, std::min({std::abs(r - rt), std::abs(r - rr), std::abs(r - ri)}));
        }
      }
    }
  std::printf("[ geo3d ] extruded tooth: flank %.1e (%u), fillet %.1e (%u), circles %.1e\n",
              flank,
              n_flank,
              fillet,
              n_fillet,
              circle);
  EXPECT_GT(n_flank, 100u);
  EXPECT_GT(n_fillet, 10u);
  EXPECT_LT(flank, 1e-10 * rt);
  EXPECT_LT(fillet, 1e-10 * rt);
  EXPECT_LT(circle, 1e-10 * rt);
}

// The mid-plane z = 0 (the symmetry face) of the refined extruded tooth is the refined 2D tooth
// mesh: the same vertices to 1e-10 of the tip radius (new points on the plane come from the same
// 2D manifolds and the transfinite interpolation restricted to the plane). Volume and areas
// against the 2D mesh x half face width, with the same mapping degree (2) in both: the 3D cells
// are exact extrusions, so the difference is the round-off of the transfinite charts: 1e-9.
// The inner arc against r_i * (2 pi / z) * teeth * h (mapping error O(h^3): 1e-6).
TEST(Workpiece3d, ExtrudedGearToothMidPlaneEqualsTwoDimensionalMesh)
{
  const GeometryParameters p3 = tooth(2, true), p2 = tooth(2, false);
  Triangulation<3>         tria3;
  Triangulation<2>         tria2;
  create_workpiece(p3, tria3);
  create_workpiece(p2, tria2);
  const double h = 0.5 * p3.gear_face_width, rt = p3.gear_tooth.gear().tip_radius();

  std::vector<Point<2>> plane;
  for (const auto &x : tria3.get_vertices())
    if (std::abs(x[2]) < 1e-12)
      plane.emplace_back(x[0], x[1]);
  const std::vector<Point<2>> &flat = tria2.get_vertices();
  ASSERT_EQ(plane.size(), tria2.n_used_vertices());
  double worst = 0.;
  for (const Point<2> &x : plane)
  {
    double nearest = 1e300;
    for (unsigned int i = 0; i < flat.size(); ++i)
      if (tria2.vertex_used(i))
        nearest = std::min(nearest, x.distance(flat[i]));
    worst = std::max(worst, nearest);
  }
  std::printf("[ geo3d ] extruded tooth mid-plane: %zu vertices, max distance to 2D %.1e\n",
              plane.size(),
              worst);
  EXPECT_LT(worst, 1e-10 * rt);

  const auto [volume, area] = measure(tria3, 2);
  const auto [area2, length] = measure(tria2, 2);
  std::printf("[ geo3d ] extruded tooth: volume / (2D area h) - 1 = %.1e\n",
              volume / (area2 * h) - 1.);
  EXPECT_NEAR(volume, area2 * h, 1e-9 * area2 * h);
  namespace ids = boundary_ids_3d::extruded_gear_tooth;
  EXPECT_LT(area_error(area,
                       {{ids::outline, length.at(gear_tooth_ids::outline) * h},
                        {ids::inner_arc, length.at(gear_tooth_ids::inner_arc) * h},
                        {ids::side_cuts, length.at(gear_tooth_ids::side_cuts) * h},
                        {ids::face_end, area2},
                        {ids::symmetry, area2}},
                       area2),
            1e-9);
  const double arc = p3.gear_tooth.inner_radius() * 2. * M_PI / p3.gear_tooth.size.teeth * 2. * h;
  EXPECT_NEAR(area.at(ids::inner_arc), arc, 1e-6 * arc);
}

// Graded layers (Layer ratio): 3 coarse layers with ratio 0.25 through the 3 mm half face have
// the thicknesses h, h q, h q^2 with q = 0.5 (h = 3 / 1.75), i.e. the planes z = 0, 1.714,
// 2.571, 3 mm (exact sums, 1e-12); one refinement halves each layer; the volume equals that of
// uniform layers (1e-10: the same extruded section) and the face-end plane is still id 3.
TEST(Workpiece3d, ExtrudedGearToothGradedLayers)
{
  GeometryParameters p = tooth(1, true);
  p.gear_layers = 3;
  p.gear_layer_ratio = 0.25;
  p.global_refinements = 1;
  Triangulation<3> graded, uniform;
  create_workpiece(p, graded);
  p.gear_layer_ratio = 1.;
  create_workpiece(p, uniform);
  std::set<long> planes;
  for (const auto &x : graded.get_vertices())
    planes.insert(std::lround(x[2] * 1e9));
  const double        h = 3. / 1.75;
  std::vector<double> expected;
  for (const double z0 : {0., h, 1.5 * h})
  {
    const double dz = (z0 == 0. ? h : z0 == h ? 0.5 * h : 0.25 * h);
    expected.push_back(z0);
    expected.push_back(z0 + 0.5 * dz);
  }
  expected.push_back(3.);
  ASSERT_EQ(planes.size(), expected.size());
  unsigned int i = 0;
  for (const long z : planes)
    EXPECT_NEAR(z * 1e-9, expected[i++], 1e-9);
  EXPECT_NEAR(
      measure(graded, 2).first, measure(uniform, 2).first, 1e-10 * measure(uniform, 2).first);
  for (const auto &cell : graded.active_cell_iterators())
    for (const auto &face : cell->face_iterators())
      if (face->at_boundary() && std::abs(face->center()[2] - 3.) < 1e-9)
        EXPECT_EQ(face->boundary_id(), boundary_ids_3d::extruded_gear_tooth::face_end);
  EXPECT_THROW(parse("set Type = extruded gear tooth\nsubsection Extruded gear tooth\n"
                     "set Layer ratio = 0\nend"),
               InputError);
}

// A 3D shape in a 2D run and a 2D shape in a 3D run are input errors naming Geometry/Type; bad
// sizes name their entry.
TEST(Workpiece3d, InputErrorsNameTheEntry)
{
  const auto message = [](auto &&build)
  {
    try
    {
      build();
    }
    catch (const InputError &e)
    {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  for (const std::string type : {"block", "quarter cylinder", "thick ring", "extruded gear tooth"})
  {
    const GeometryParameters p = parse("set Type = " + type);
    EXPECT_EQ(p.dimension(), 3u);
    Triangulation<2>  tria;
    const std::string m = message([&] { create_workpiece(p, tria); });
    EXPECT_NE(m.find("Geometry/Type: '" + type + "' is three-dimensional"), std::string::npos) << m;
    EXPECT_NE(m.find("the run is 2D"), std::string::npos) << m;
  }
  for (const std::string type : {"rectangle", "gear tooth", "ring"})
  {
    const GeometryParameters p = parse("set Type = " + type);
    Triangulation<3>         tria;
    const std::string        m = message([&] { create_workpiece(p, tria); });
    EXPECT_NE(m.find("Geometry/Type: '" + type + "' is two-dimensional"), std::string::npos) << m;
  }
  EXPECT_NE(
      message([] { parse("set Type = block\nsubsection Block\nset Upper corner = 1, 0, 1\nend"); })
          .find("Geometry/Block/Upper corner"),
      std::string::npos);
  EXPECT_NE(message(
                []
                {
                  parse("set Type = quarter cylinder\nsubsection Quarter cylinder\n"
                        "set Radius = -1\nend");
                })
                .find("Geometry/Quarter cylinder/Radius"),
            std::string::npos);
  EXPECT_NE(message(
                []
                {
                  parse("set Type = thick ring\nsubsection Thick ring\n"
                        "set Thickness = 0\nend");
                })
                .find("Geometry/Thick ring/Thickness"),
            std::string::npos);
  EXPECT_NE(message(
                []
                {
                  parse("set Type = extruded gear tooth\nsubsection Extruded gear tooth\n"
                        "set Face width = 0\nend");
                })
                .find("Geometry/Extruded gear tooth/Face width"),
            std::string::npos);
  EXPECT_NE(message(
                []
                {
                  parse("set Type = thick ring\nsubsection Ring\n"
                        "set Outer radius = 0.5\nend");
                })
                .find("Geometry/Ring/Outer radius"),
            std::string::npos);
  // more coarse cells than accepted
  {
    const GeometryParameters p
        = parse("set Type = block\nsubsection Block\nset Cells = 200, 200, 200\nend");
    Triangulation<3> tria;
    EXPECT_NE(message([&] { create_workpiece(p, tria); }).find("Geometry/Block/Cells"),
              std::string::npos);
  }
}
