#include <ausroll/contact/die_surface.h>
#include <ausroll/contact/surfaces/arc_line.h>
#include <ausroll/core/exceptions.h>
#include <ausroll/core/parse_utilities.h>

namespace ausroll::contact::surfaces
{
  using namespace dealii;

  void ArcLineParameters::declare_parameters(ParameterHandler &prm)
  {
    DiePoints::declare_parameters(prm);
    prm.declare_entry("Fillet radii",
                      "",
                      Patterns::Anything(),
                      "Radius of the tangent arc at each interior corner (one value for all, or "
                      "one per corner; mm).");
  }

  void ArcLineParameters::parse(ParameterHandler  &prm,
                                const std::string &path,
                                const std::string &input_directory)
  {
    outline.parse(prm, path, input_directory);
    fillet_radii = parse_double_list(prm.get("Fillet radii"), path + "Fillet radii");
    require(!fillet_radii.empty(), path + "Fillet radii", "needs at least one radius");
  }

  std::unique_ptr<const RigidSurface<2>> ArcLineParameters::create(const std::string &path) const
  {
    const std::vector<Point<2>> points = outline.read(path);
    try
    {
      return std::make_unique<ChainSurface>(
          "arc line", DieSurface::arc_line_composite(points, fillet_radii, false, true));
    }
    catch (const std::exception &e)
    {
      throw InputError(path + "Points: " + e.what());
    }
  }
} // namespace ausroll::contact::surfaces

AUSROLL_REGISTER_DIE_SHAPE(2,
                           ausroll::contact::surfaces::ArcLineParameters,
                           "arc line",
                           "Arc line",
                           "a polyline with tangent fillet arcs at its corners")
