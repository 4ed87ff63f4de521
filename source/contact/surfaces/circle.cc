#include <ausroll/contact/die_surface.h>
#include <ausroll/contact/surfaces/circle.h>
#include <ausroll/core/exceptions.h>
#include <ausroll/core/parse_utilities.h>

namespace ausroll::contact::surfaces
{
  using namespace dealii;

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
    return std::make_unique<ChainSurface>("circle",
                                          DieSurface::circle(center, radius, material_inside));
  }
} // namespace ausroll::contact::surfaces

AUSROLL_REGISTER_DIE_SHAPE(2,
                           ausroll::contact::surfaces::CircleParameters,
                           "circle",
                           "Circle",
                           "a full circle (roll, round punch, or a hole)")
