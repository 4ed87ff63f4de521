#include <ausroll/contact/surfaces/cone.h>
#include <ausroll/contact/surfaces/shape_entries_3d.h>
#include <ausroll/core/exceptions.h>

#include <deal.II/base/numbers.h>

#include <cmath>

namespace ausroll::contact::surfaces
{
  using namespace dealii;

  Cone::Cone(const Point<3>     &apex,
             const Tensor<1, 3> &axis,
             const double        half_angle,
             const Tensor<1, 3> &reference)
      : frame(apex, axis, reference)
      , sin_alpha(std::sin(half_angle))
      , cos_alpha(std::cos(half_angle))
  {
    if (!(half_angle > 0.) || !(half_angle < 0.5 * numbers::PI))
      throw EntryError("Half angle", "must lie strictly between 0 and 90 degrees");
  }

  MeridianProjection Cone::project_meridian(const double r, const double z) const
  {
    MeridianProjection m;
    const double       rho = r * sin_alpha + z * cos_alpha; // along the generator
    if (rho > 0.)
    {
      m.point = Point<2>(rho * sin_alpha, rho * cos_alpha);
      m.normal = Tensor<1, 2>({cos_alpha, -sin_alpha});
      m.gap = r * cos_alpha - z * sin_alpha;
      m.s = -rho;
      return m;
    }
    // behind the apex: the apex is the closest point, a vertex
    const double d = std::hypot(r, z);
    m.point = Point<2>(0., 0.);
    m.normal = d > 0. ? Tensor<1, 2>({r / d, z / d}) : Tensor<1, 2>({cos_alpha, -sin_alpha});
    m.gap = d;
    m.s = 0.;
    m.at_edge = true;
    return m;
  }

  SurfaceProjection<3> Cone::project(const Point<3> &x, const double max_distance) const
  {
    const Point<3>           xi = frame.to_canonical(x);
    const MeridianProjection m = project_meridian(std::hypot(xi[0], xi[1]), xi[2]);
    if (!(std::abs(m.gap) <= max_distance))
      return SurfaceProjection<3>();
    SurfaceProjection<3> p = revolve_meridian_projection(xi, m, 0.);
    frame.to_local(p);
    return p;
  }

  void ConeParameters::declare_parameters(ParameterHandler &prm)
  {
    declare_placement(prm,
                      "Apex",
                      "Apex of the cone (x, y, z).",
                      "Direction of the cone axis from the apex into the cone, i.e. into the die "
                      "material (nonzero).",
                      "Direction of theta = 0 for the surface coordinates.");
    prm.declare_entry("Half angle",
                      "45",
                      Patterns::Double(0., 90.),
                      "Half opening angle alpha between the axis and the surface (degrees, "
                      "0 < alpha < 90).");
  }

  void ConeParameters::parse(ParameterHandler &prm, const std::string &path, const std::string &)
  {
    parse_placement(prm, "Apex", path, apex, axis, reference);
    half_angle = prm.get_double("Half angle");
  }

  std::unique_ptr<const RigidSurface<3>> ConeParameters::create(const std::string &path) const
  {
    return with_path(
        path,
        [&]() -> std::unique_ptr<const RigidSurface<3>>
        { return std::make_unique<Cone>(apex, axis, half_angle * numbers::PI / 180., reference); });
  }
} // namespace ausroll::contact::surfaces

AUSROLL_REGISTER_DIE_SHAPE(3,
                           ausroll::contact::surfaces::ConeParameters,
                           "cone",
                           "Cone",
                           "an infinite circular cone of Half angle about Axis (a conical punch "
                           "tip), die material inside")
