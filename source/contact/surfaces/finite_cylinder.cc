#include <ausroll/contact/surfaces/finite_cylinder.h>
#include <ausroll/contact/surfaces/shape_entries_3d.h>
#include <ausroll/core/exceptions.h>
#include <ausroll/core/parse_utilities.h>

#include <deal.II/base/numbers.h>

#include <algorithm>
#include <cmath>

namespace ausroll::contact::surfaces
{
  using namespace dealii;

  FiniteCylinder::FiniteCylinder(const Point<3>     &center,
                                 const Tensor<1, 3> &axis,
                                 const double        radius,
                                 const double        width,
                                 const double        edge_radius,
                                 const Tensor<1, 3> &reference)
      : frame(center, axis, reference)
      , R(radius)
      , h(0.5 * width)
      , re(edge_radius)
  {
    if (!(radius > 0.) || !std::isfinite(radius))
      throw EntryError("Radius", "must be positive");
    if (!(width > 0.) || !std::isfinite(width))
      throw EntryError("Width", "must be positive");
    if (!(edge_radius >= 0.) || edge_radius > radius || edge_radius > h)
      throw EntryError("Edge radius", "must lie in [0, min(Radius, Width / 2)]");
  }

  MeridianProjection FiniteCylinder::project_meridian(const double r, const double z) const
  {
    const double a = R - re, b = h - re; // the inner box [0, a] x [-b, b]
    const double v = std::abs(z), sz = z >= 0. ? 1. : -1.;
    const double quarter = 0.5 * numbers::PI * re;
    // s at the start of the mantle and at the start of the lower rim
    const double s_mantle = a + quarter, s_lower = s_mantle + 2. * b;

    MeridianProjection m;
    auto               face = [&]()
    {
      m.point = Point<2>(r, sz * h);
      m.normal = Tensor<1, 2>({0., sz});
      m.gap = v - h;
      m.s = sz > 0. ? r : s_lower + quarter + (a - r);
    };
    auto mantle = [&]()
    {
      m.point = Point<2>(R, z);
      m.normal = Tensor<1, 2>({1., 0.});
      m.gap = r - R;
      m.s = s_mantle + (b - z);
    };
    if (r > a && v > b)
    {
      // rim: around the corner centre (a, sz b)
      const double dr = r - a, dv = v - b, d = std::hypot(dr, dv);
      m.normal = Tensor<1, 2>({dr / d, sz * dv / d});
      m.point = Point<2>(a + re * m.normal[0], sz * b + re * m.normal[1]);
      m.gap = d - re;
      const double alpha = std::atan2(dr, dv); // from the face (0) to the mantle (pi / 2)
      m.s = sz > 0. ? a + re * alpha : s_lower + re * (0.5 * numbers::PI - alpha);
      if (re > 0.)
        m.curvature = 1. / re;
      else
        m.at_edge = true;
    }
    else if (r > a)
      mantle();
    else if (v > b)
      face();
    else if (R - r <= h - v)
      mantle(); // inside the core: the nearer flat part
    else
      face();
    return m;
  }

  SurfaceProjection<3> FiniteCylinder::project(const Point<3> &x, const double max_distance) const
  {
    const Point<3>           xi = frame.to_canonical(x);
    const double             r = std::hypot(xi[0], xi[1]);
    const MeridianProjection m = project_meridian(r, xi[2]);
    if (!(std::abs(m.gap) <= max_distance))
      return SurfaceProjection<3>();
    SurfaceProjection<3> p = revolve_meridian_projection(xi, m, 1e-14 * (R + h));
    frame.to_local(p);
    return p;
  }

  Point<3> FiniteCylinder::point_at(const std::array<double, 2> &coordinates) const
  {
    // the meridian profile of project_meridian(), travelled by s
    const double a = R - re, b = h - re, quarter = 0.5 * numbers::PI * re;
    const double s_mantle = a + quarter, s_lower = s_mantle + 2. * b;
    const double s = std::clamp(coordinates[0], 0., s_lower + quarter + a);
    double       r, z;
    if (s <= a)
      r = s, z = h; // upper face
    else if (s <= s_mantle)
    {
      const double alpha = re > 0. ? (s - a) / re : 0.; // from the face to the mantle
      r = a + re * std::sin(alpha), z = b + re * std::cos(alpha);
    }
    else if (s <= s_lower)
      r = R, z = b - (s - s_mantle);
    else if (s <= s_lower + quarter)
    {
      const double alpha = re > 0. ? 0.5 * numbers::PI - (s - s_lower) / re : 0.;
      r = a + re * std::sin(alpha), z = -b - re * std::cos(alpha);
    }
    else
      r = a - (s - s_lower - quarter), z = -h; // lower face
    const double theta = coordinates[1];
    return frame.to_local(Point<3>(r * std::cos(theta), r * std::sin(theta), z));
  }

  void CylinderParameters::declare_parameters(ParameterHandler &prm)
  {
    declare_placement(prm,
                      "Center",
                      "Centre of the cylinder: on the axis, mid-way across the width (x, y, z).",
                      "Direction of the cylinder axis (nonzero).",
                      "Direction of theta = 0 for the surface coordinates (its part normal to "
                      "the axis).");
    prm.declare_entry("Radius", "1", Patterns::Double(0.), "Radius R (mm).");
    prm.declare_entry("Width", "1", Patterns::Double(0.), "Width w along the axis (mm).");
    prm.declare_entry("Edge radius",
                      "0",
                      Patterns::Double(0.),
                      "Radius r_e rounding the two rim edges (mm; 0: sharp; at most "
                      "min(Radius, Width / 2)).");
  }

  void
  CylinderParameters::parse(ParameterHandler &prm, const std::string &path, const std::string &)
  {
    parse_placement(prm, "Center", path, center, axis, reference);
    radius = prm.get_double("Radius");
    width = prm.get_double("Width");
    edge_radius = prm.get_double("Edge radius");
  }

  std::unique_ptr<const RigidSurface<3>> CylinderParameters::create(const std::string &path) const
  {
    return with_path(path,
                     [&]() -> std::unique_ptr<const RigidSurface<3>> {
                       return std::make_unique<FiniteCylinder>(
                           center, axis, radius, width, edge_radius, reference);
                     });
  }
} // namespace ausroll::contact::surfaces

AUSROLL_REGISTER_DIE_SHAPE(
    3,
    ausroll::contact::surfaces::CylinderParameters,
    "cylinder",
    "Cylinder",
    "a cylinder of finite Width with flat faces and rounded rim edges (a roll)")
