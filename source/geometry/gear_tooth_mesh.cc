/**
 * @file gear_tooth_mesh.cc
 * Coarse mesh of an involute gear tooth sector (see gear_tooth_mesh.h for ids and layout).
 */
#include <ausroll/core/exceptions.h>
#include <ausroll/geometry/flank_manifold.h>
#include <ausroll/geometry/gear_entries.h>
#include <ausroll/geometry/gear_tooth_mesh.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria_description.h>

#include <array>
#include <cmath>

namespace ausroll::geometry
{
  using namespace dealii;

  namespace
  {
    const std::string section = "Geometry/Gear tooth/";

    /** Point at polar coordinates (@p r, @p phi). */
    Point<2> polar(const double r, const double phi)
    {
      return Point<2>(r * std::cos(phi), r * std::sin(phi));
    }

    /** @p p rotated about the origin by @p angle. */
    Point<2> rotated(const Point<2> &p, const double angle)
    {
      const double c = std::cos(angle), s = std::sin(angle);
      return Point<2>(c * p[0] - s * p[1], s * p[0] + c * p[1]);
    }

    /** Quadrilaterals given by their corners, with vertices merged within a tolerance. */
    struct QuadCollector
    {
      /** Merge tolerance (mm). */
      double tolerance;
      /** Distinct vertices. */
      std::vector<Point<2>> vertices;
      /** Cells in deal.II's lexicographic vertex order. */
      std::vector<CellData<2>> cells;

      /** Index of @p p, adding it if no vertex lies within the tolerance. */
      unsigned int vertex(const Point<2> &p)
      {
        for (unsigned int i = 0; i < vertices.size(); ++i)
          if (vertices[i].distance(p) < tolerance)
            return i;
        vertices.push_back(p);
        return vertices.size() - 1;
      }

      /** Add the quadrilateral with corners @p c in cyclic order (either orientation). */
      void add(std::array<Point<2>, 4> c)
      {
        double area = 0.;
        for (unsigned int i = 0; i < 4; ++i)
          area += c[i][0] * c[(i + 1) % 4][1] - c[(i + 1) % 4][0] * c[i][1];
        if (area < 0.)
          std::swap(c[1], c[3]);
        CellData<2> cell;
        cell.vertices = {vertex(c[0]), vertex(c[1]), vertex(c[3]), vertex(c[2])};
        cells.push_back(cell);
      }
    };

    /**
     * Cells of the positive half (0 <= polar angle <= pi/z) of the reference tooth (axis +x),
     * each as four corners in cyclic order.
     */
    std::vector<std::array<Point<2>, 4>> positive_half(const InvoluteGear &g, const double r_inner)
    {
      std::vector<std::array<Point<2>, 4>> quads;
      const ToothGeometry                 &t = g.tooth_geometry();
      const double rt = g.tip_radius(), rp = g.pitch_radius(), rr = g.root_radius();
      const double rs = t.flank_start_radius;
      const double half_space = M_PI / g.n_teeth();

      // Tooth: 4 rows between tip, pitch and fillet start, 2 columns (axis, middle, flank).
      const std::array<double, 5> levels = {{rt, 0.5 * (rt + rp), rp, 0.5 * (rp + rs), rs}};
      for (unsigned int j = 0; j + 1 < levels.size(); ++j)
      {
        const double   hi = levels[j], lo = levels[j + 1];
        const Point<2> a_hi(hi, 0.), a_lo(lo, 0.);
        const Point<2> m_hi = polar(hi, 0.5 * g.half_thickness_angle(hi));
        const Point<2> m_lo = polar(lo, 0.5 * g.half_thickness_angle(lo));
        const Point<2> f_hi = g.flank_point(hi, FlankSide::positive);
        const Point<2> f_lo = g.flank_point(lo, FlankSide::positive);
        quads.push_back({{a_lo, a_hi, m_hi, m_lo}});
        quads.push_back({{m_lo, m_hi, f_hi, f_lo}});
      }

      // Rim: columns below the tooth (axis, middle, fillet start), under the fillet and under
      // the root land, fanning out to equal angles at the inner arc.
      std::vector<Point<2>> top = {Point<2>(rs, 0.),
                                   polar(rs, 0.5 * g.half_thickness_angle(rs)),
                                   g.flank_point(rs, FlankSide::positive)};
      const double          tol = 1e-9 * rt;
      const Point<2>        q = polar(rr, t.root_land_angle);
      if (q.distance(top.back()) > tol)
        top.push_back(q);
      const Point<2> s = polar(rr, half_space);
      if (s.distance(top.back()) > tol)
        top.push_back(s);
      const unsigned int  n_columns = top.size() - 1;
      std::vector<double> top_angle(top.size());
      double              d1 = rt - rr;
      for (unsigned int i = 0; i <= n_columns; ++i)
      {
        top_angle[i] = std::atan2(top[i][1], top[i][0]);
        if (i > 0)
          d1 = std::min(d1, top[i].distance(top[i - 1]));
      }
      top_angle.back() = half_space;

      // Radii of the rim levels: first layer about as thick as the narrowest column, then
      // growing by 1.6 towards the inner arc.
      std::vector<double> radii;
      if (rr - r_inner > 1.5 * d1)
      {
        double r = rr - d1, h = d1;
        radii.push_back(r);
        while (r - 1.6 * h > r_inner + 0.8 * h)
        {
          h *= 1.6;
          r -= h;
          radii.push_back(r);
        }
      }
      radii.push_back(r_inner);
      const double r_first = radii.front();
      const auto   level_point = [&](const double r, const unsigned int i)
      {
        const double w = (radii.size() == 1) ? 1. : (r_first - r) / (r_first - r_inner);
        const double phi
            = (1. - w) * top_angle[i] + w * half_space * static_cast<double>(i) / n_columns;
        return polar(r, phi);
      };
      std::vector<Point<2>> upper = top;
      for (const double r : radii)
      {
        std::vector<Point<2>> lower(top.size());
        for (unsigned int i = 0; i <= n_columns; ++i)
          lower[i] = level_point(r, i);
        for (unsigned int i = 0; i < n_columns; ++i)
          quads.push_back({{lower[i], lower[i + 1], upper[i + 1], upper[i]}});
        upper = lower;
      }
      return quads;
    }
  } // namespace

  void GearToothParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Gear tooth");
    declare_gear_size_entries(prm, "31", "Teeth z of the whole gear.");
    prm.declare_entry("Tooth thickness",
                      "-1",
                      Patterns::Double(),
                      "Arc tooth thickness at the pitch circle (mm); negative: half the circular "
                      "pitch (the thesis gear: 0.1848 inch).");
    prm.declare_entry("Root fillet radius",
                      "0",
                      Patterns::Double(0.),
                      "Radius of the circular fillet between root circle and flank (mm).");
    prm.declare_entry("Rim thickness",
                      "-1",
                      Patterns::Double(),
                      "Depth of the rim below the root circle down to the inner arc (boundary 1) "
                      "(mm); negative: the whole depth addendum + dedendum.");
    prm.declare_entry("Tooth axis angle",
                      "90",
                      Patterns::Double(),
                      "Polar angle of the axis of the middle tooth of the sector about the gear "
                      "centre (the origin) (degrees).");
    prm.declare_entry("Teeth", "1", Patterns::Integer(1), "Number of teeth in the meshed sector.");
    prm.declare_entry("Fix root",
                      "false",
                      Patterns::Bool(),
                      "true: the side cuts get boundary id 1 like the inner arc, so that fixing "
                      "id 1 clamps the whole rim (the tooth only deforms above it); false: side "
                      "cuts keep id 2 and the rim can bend with the tooth.");
    prm.leave_subsection();
  }

  void GearToothParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Gear tooth");
    size.parse(prm);
    tooth_thickness = prm.get_double("Tooth thickness");
    root_fillet_radius = prm.get_double("Root fillet radius");
    rim_thickness = prm.get_double("Rim thickness");
    tooth_axis_angle = prm.get_double("Tooth axis angle");
    teeth = prm.get_integer("Teeth");
    fix_root = prm.get_bool("Fix root");
    prm.leave_subsection();
  }

  InvoluteGear GearToothParameters::gear() const
  {
    require(size.diametral_pitch > 0. || size.module > 0.,
            section + "Module",
            "set Diametral pitch or Module");
    require(size.pressure_angle > 0., section + "Pressure angle", "must be positive");
    require(teeth < max_sector_teeth(),
            section + "Teeth",
            std::to_string(teeth) + " is outside the allowed range 1 to "
                + std::to_string(max_sector_teeth() - 1)
                + ": the mesh is a sector of the gear (Number of teeth = "
                + std::to_string(size.teeth)
                + ") with cut edges as boundaries 2 and 3, at most half the gear");
    ToothProportions p;
    if (size.addendum >= 0.)
      p.addendum = size.addendum;
    if (size.dedendum >= 0.)
      p.dedendum = size.dedendum;
    if (tooth_thickness >= 0.)
      p.pitch_tooth_thickness = tooth_thickness;
    p.root_fillet_radius = root_fillet_radius;
    try
    {
      const double alpha = size.pressure_angle * M_PI / 180.;
      return InvoluteGear::from_pitch_or_module(
          size.teeth, size.diametral_pitch, size.module, alpha, p);
    }
    catch (const EntryError &e)
    {
      throw InputError("Geometry/Gear tooth/" + e.entry() + ": " + e.what_is_wrong());
    }
    catch (const InputError &e)
    {
      throw InputError("Geometry/Gear tooth: " + std::string(e.what()));
    }
  }

  double GearToothParameters::inner_radius() const
  {
    const InvoluteGear g = gear();
    const double       rim = rim_thickness < 0. ? g.addendum() + g.dedendum() : rim_thickness;
    require(rim > 0. && rim < g.root_radius(),
            section + "Rim thickness",
            "must be positive and smaller than the root radius");
    return g.root_radius() - rim;
  }

  double GearToothParameters::axis_angle(const unsigned int k) const
  {
    return tooth_axis_angle * M_PI / 180.
           + (static_cast<double>(k) - 0.5 * (teeth - 1.)) * 2. * M_PI / size.teeth;
  }

  void create_gear_tooth_mesh(const GearToothParameters &p, Triangulation<2> &coarse)
  {
    const InvoluteGear g = p.gear();
    const double       r_inner = p.inner_radius();
    const double       half_space = M_PI / g.n_teeth();
    const auto         half = positive_half(g, r_inner);

    QuadCollector collector{1e-9 * g.tip_radius(), {}, {}};
    for (unsigned int k = 0; k < p.teeth; ++k)
      for (const auto &quad : half)
      {
        std::array<Point<2>, 4> pos, neg;
        for (unsigned int i = 0; i < 4; ++i)
        {
          pos[i] = rotated(quad[i], p.axis_angle(k));
          neg[i] = rotated(Point<2>(quad[i][0], -quad[i][1]), p.axis_angle(k));
        }
        collector.add(pos);
        collector.add(neg);
      }
    coarse.create_triangulation(collector.vertices, collector.cells, SubCellData());

    // Boundary and manifold ids from the position of each boundary face in its tooth's frame.
    coarse.set_all_manifold_ids(2);
    const double         tol = 1e-8 * g.tip_radius();
    const ToothGeometry &t = g.tooth_geometry();
    for (const auto &cell : coarse.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
      {
        if (!face->at_boundary())
          continue;
        const double phi_c = std::atan2(face->center()[1], face->center()[0]);
        const double k_real
            = std::remainder(phi_c - p.axis_angle(0), 2. * M_PI) / (2. * half_space);
        const unsigned int k = static_cast<unsigned int>(
            std::clamp(std::round(k_real), 0., static_cast<double>(p.teeth - 1)));
        std::array<Point<2>, 2> v;
        for (unsigned int i = 0; i < 2; ++i)
          v[i] = rotated(face->vertex(i), -p.axis_angle(k));
        const auto   on = [&](const auto &predicate) { return predicate(v[0]) && predicate(v[1]); };
        const double side = (v[0][1] + v[1][1] > 0.) ? 1. : -1.;
        const unsigned int base = 10 + 10 * k + (side > 0. ? 0 : 1);
        if (on([&](const Point<2> &x) { return std::abs(x.norm() - r_inner) < tol; }))
        {
          face->set_boundary_id(gear_tooth_ids::inner_arc);
          face->set_manifold_id(1);
        }
        else if (on([&](const Point<2> &x)
                    { return std::abs(std::abs(std::atan2(x[1], x[0])) - half_space) < 1e-9; }))
        {
          face->set_boundary_id(p.fix_root ? gear_tooth_ids::inner_arc : gear_tooth_ids::side_cuts);
          face->set_manifold_id(numbers::flat_manifold_id);
        }
        else
        {
          face->set_boundary_id(gear_tooth_ids::outline);
          const Point<2> fillet_center(t.fillet_center[0], side * t.fillet_center[1]);
          if (on([&](const Point<2> &x) { return std::abs(x.norm() - g.tip_radius()) < tol; })
              || on([&](const Point<2> &x) { return std::abs(x.norm() - g.root_radius()) < tol; }))
            face->set_manifold_id(1);
          else if (g.root_fillet_radius() > 0.
                   && on(
                       [&](const Point<2> &x) {
                         return std::abs(x.distance(fillet_center) - g.root_fillet_radius()) < tol;
                       }))
            face->set_manifold_id(base + 2);
          else
            face->set_manifold_id(base);
        }
      }
  }

  void attach_gear_tooth_manifolds(const GearToothParameters &p, Triangulation<2> &tria)
  {
    const InvoluteGear g = p.gear();
    tria.set_manifold(1, PolarManifold<2>(Point<2>()));
    const Point<2> c = g.tooth_geometry().fillet_center;
    for (unsigned int k = 0; k < p.teeth; ++k)
    {
      const double       axis = p.axis_angle(k);
      const unsigned int base = 10 + 10 * k;
      tria.set_manifold(base, FlankManifold(g, FlankSide::positive, axis));
      tria.set_manifold(base + 1, FlankManifold(g, FlankSide::negative, axis));
      if (g.root_fillet_radius() > 0.)
      {
        tria.set_manifold(base + 2, PolarManifold<2>(rotated(c, axis)));
        tria.set_manifold(base + 3, PolarManifold<2>(rotated(Point<2>(c[0], -c[1]), axis)));
      }
    }
    TransfiniteInterpolationManifold<2> transfinite;
    transfinite.initialize(tria);
    tria.set_manifold(2, transfinite);
  }

  void create_extruded_gear_tooth_mesh(const GearToothParameters &p,
                                       const double               half_width,
                                       const unsigned int         layers,
                                       Triangulation<3>          &coarse,
                                       const double               layer_ratio)
  {
    Triangulation<2> section;
    create_gear_tooth_mesh(p, section);
    // layer i has the thickness h q^i, q^(layers - 1) = layer_ratio, the layers sum to half_width
    const double        q = layers > 1 ? std::pow(layer_ratio, 1. / (layers - 1.)) : 1.;
    std::vector<double> z(layers + 1, 0.);
    for (unsigned int i = 1; i <= layers; ++i)
      z[i] = z[i - 1] + std::pow(q, i - 1.);
    for (double &zi : z)
      zi *= half_width / z[layers];
    z[layers] = half_width;
    // Lines along z through a vertex of the outline take the outline's manifold (they are
    // straight in every chart used here), interior ones the transfinite id.
    std::vector<types::manifold_id> priorities;
    for (unsigned int k = 0; k < p.teeth; ++k)
      for (unsigned int j = 0; j < 4; ++j)
        priorities.push_back(10 + 10 * k + j);
    priorities.push_back(1);
    priorities.push_back(numbers::flat_manifold_id);
    priorities.push_back(2);
    GridGenerator::extrude_triangulation(
        section, z, coarse, /*copy_manifold_ids=*/true, priorities);
    const double tol = 1e-8 * half_width;
    for (const auto &cell : coarse.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
        {
          const double zc = face->center()[2];
          if (std::abs(zc) < tol)
            face->set_boundary_id(4);
          else if (std::abs(zc - half_width) < tol)
            face->set_boundary_id(3);
        }
  }

  void attach_extruded_gear_tooth_manifolds(const GearToothParameters &p, Triangulation<3> &tria)
  {
    const InvoluteGear g = p.gear();
    const Tensor<1, 3> e_z({0., 0., 1.});
    tria.set_manifold(1, CylindricalManifold<3>(e_z, Point<3>()));
    const Point<2> c = g.tooth_geometry().fillet_center;
    for (unsigned int k = 0; k < p.teeth; ++k)
    {
      const double       axis = p.axis_angle(k);
      const unsigned int base = 10 + 10 * k;
      tria.set_manifold(base, ExtrudedFlankManifold(g, FlankSide::positive, axis));
      tria.set_manifold(base + 1, ExtrudedFlankManifold(g, FlankSide::negative, axis));
      if (g.root_fillet_radius() > 0.)
        for (const double side : {1., -1.})
        {
          const Point<2> f = rotated(Point<2>(c[0], side * c[1]), axis);
          tria.set_manifold(base + (side > 0. ? 2 : 3),
                            CylindricalManifold<3>(e_z, Point<3>(f[0], f[1], 0.)));
        }
    }
    TransfiniteInterpolationManifold<3> transfinite;
    transfinite.initialize(tria);
    tria.set_manifold(2, transfinite);
  }
} // namespace ausroll::geometry
