#include <ausroll/contact/surfaces/chain_surface.h>
#include <ausroll/contact/surfaces/circle.h>
#include <ausroll/core/exceptions.h>
#include <ausroll/core/parse_utilities.h>
#include <ausroll/geometry/plane_vectors.h>

namespace ausroll::contact::surfaces
{
  using namespace dealii;
  using namespace geometry::plane;

  geometry::CurveChain
  circle_chain(const Point<2> &center, const double radius, const bool material_inside)
  {
    return geometry::CurveChain(
        {geometry::CurveSegment::arc(
            center, radius, 0.0, material_inside ? -2.0 * M_PI : 2.0 * M_PI)},
        true);
  }

  void CircleParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Center", "0, 0", Patterns::Anything(), "Centre of the circle.");
    prm.declare_entry("Radius", "1", Patterns::Double(0.), "Radius (mm).");
    prm.declare_entry("Material inside",
                      "true",
                      Patterns::Bool(),
                      "true for a roll or punch (die material inside), false for a hole.");
  }

  void CircleParameters::parse(ParameterHandler &prm, const std::string &path, const std::string &)
  {
    center = parse_point<2>(prm.get("Center"), path + "Center");
    radius = prm.get_double("Radius");
    material_inside = prm.get_bool("Material inside");
    require(radius > 0., path + "Radius", "must be positive");
  }

  std::unique_ptr<const RigidSurface<2>> CircleParameters::create(const std::string &) const
  {
    return std::make_unique<ChainSurface>("circle", circle_chain(center, radius, material_inside));
  }
} // namespace ausroll::contact::surfaces

AUSROLL_REGISTER_DIE_SHAPE(2,
                           ausroll::contact::surfaces::CircleParameters,
                           "circle",
                           "Circle",
                           "a full circle (roll, round punch, or a hole)")
