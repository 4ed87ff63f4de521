#include <ausroll/contact/surfaces/shape_entries_3d.h>
#include <ausroll/contact/surfaces/torus.h>
#include <ausroll/core/exceptions.h>
#include <ausroll/core/parse_utilities.h>

#include <deal.II/base/numbers.h>

#include <cmath>

namespace ausroll::contact::surfaces
{
  using namespace dealii;

  Torus::Torus(const Point<3>     &center,
               const Tensor<1, 3> &axis,
               const double        major_radius,
               const double        minor_radius,
               const Tensor<1, 3> &reference)
      : frame(center, axis, reference)
      , R(major_radius)
      , rho(minor_radius)
  {
    if (!(major_radius > 0.) || !std::isfinite(major_radius))
      throw EntryError("Major radius", "must be positive");
    if (!(minor_radius > 0.) || !(minor_radius < major_radius))
      throw EntryError("Minor radius", "must be positive and smaller than Major radius");
  }

  MeridianProjection Torus::project_meridian(const double r, const double z) const
  {
    const double       dr = r - R, d = std::hypot(dr, z);
    MeridianProjection m;
    if (d > 0.)
      m.normal = Tensor<1, 2>({dr / d, z / d});
    else
      m.normal = Tensor<1, 2>({1., 0.});
    m.point = Point<2>(R + rho * m.normal[0], rho * m.normal[1]);
    m.gap = d - rho;
    m.curvature = 1. / rho;
    // clockwise from the outermost point: s = -rho phi in [0, 2 pi rho)
    double s = -rho * std::atan2(m.normal[1], m.normal[0]);
    if (s < 0.)
      s += 2. * numbers::PI * rho;
    m.s = s;
    return m;
  }

  SurfaceProjection<3> Torus::project(const Point<3> &x, const double max_distance) const
  {
    const Point<3>           xi = frame.to_canonical(x);
    const MeridianProjection m = project_meridian(std::hypot(xi[0], xi[1]), xi[2]);
    if (!(std::abs(m.gap) <= max_distance))
      return SurfaceProjection<3>();
    SurfaceProjection<3> p = revolve_meridian_projection(xi, m, 1e-14 * R);
    frame.to_local(p);
    return p;
  }

  Point<3> Torus::point_at(const std::array<double, 2> &coordinates) const
  {
    // s = -rho phi (project_meridian()); cos and sin wrap both coordinates
    const double phi = -coordinates[0] / rho, theta = coordinates[1];
    const double r = R + rho * std::cos(phi), z = rho * std::sin(phi);
    return frame.to_local(Point<3>(r * std::cos(theta), r * std::sin(theta), z));
  }

  void TorusParameters::declare_parameters(ParameterHandler &prm)
  {
    declare_placement(prm,
                      "Center",
                      "Centre of the torus (x, y, z).",
                      "Direction of the torus axis (the roll axis; nonzero).",
                      "Direction of theta = 0 for the surface coordinates.");
    prm.declare_entry("Major radius",
                      "2",
                      Patterns::Double(0.),
                      "R: distance from the axis to the centre of the face profile circle (mm).");
    prm.declare_entry("Minor radius",
                      "1",
                      Patterns::Double(0.),
                      "rho: radius of the face profile circle (mm), 0 < rho < R.");
  }

  void TorusParameters::parse(ParameterHandler &prm, const std::string &path, const std::string &)
  {
    parse_placement(prm, "Center", path, center, axis, reference);
    major_radius = prm.get_double("Major radius");
    minor_radius = prm.get_double("Minor radius");
  }

  std::unique_ptr<const RigidSurface<3>> TorusParameters::create(const std::string &path) const
  {
    return with_path(
        path,
        [&]() -> std::unique_ptr<const RigidSurface<3>>
        { return std::make_unique<Torus>(center, axis, major_radius, minor_radius, reference); });
  }
} // namespace ausroll::contact::surfaces

AUSROLL_REGISTER_DIE_SHAPE(3,
                           ausroll::contact::surfaces::TorusParameters,
                           "torus",
                           "Torus",
                           "a torus (a roll with a round face profile)")
