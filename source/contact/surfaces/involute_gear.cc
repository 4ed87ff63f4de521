#include <ausroll/contact/die_surface.h>
#include <ausroll/contact/surfaces/involute_gear.h>
#include <ausroll/core/exceptions.h>
#include <ausroll/geometry/gear_entries.h>
#include <ausroll/geometry/involute_gear.h>

#include <deal.II/base/numbers.h>

namespace ausroll::contact::surfaces
{
  using namespace dealii;

  void InvoluteGearParameters::declare_parameters(ParameterHandler &prm)
  {
    geometry::declare_gear_size_entries(prm, "57", "Teeth z.");
    prm.declare_entry(
        "Tooth thickness",
        "-1",
        Patterns::Double(),
        "Tooth thickness at the pitch circle (mm); negative: half the circular pitch.");
    prm.declare_entry("Root fillet radius", "0", Patterns::Double(0.), "Root fillet radius (mm).");
    prm.declare_entry("Tip radius",
                      "0",
                      Patterns::Double(0.),
                      "Radius of the tip rounds, arcs tangent to the flank and the outside "
                      "circle (mm; 0: sharp tip corners).");
    prm.declare_entry("Tooth axis angle",
                      "0",
                      Patterns::Double(),
                      "Direction of the axis of tooth 0 (degrees from +x).");
    prm.declare_entry("Teeth in sector",
                      "0",
                      Patterns::Integer(0),
                      "Build only this many teeth around tooth 0 (0: whole gear).");
  }

  void
  InvoluteGearParameters::parse(ParameterHandler &prm, const std::string &path, const std::string &)
  {
    teeth = prm.get_integer("Number of teeth");
    diametral_pitch = prm.get_double("Diametral pitch");
    module = prm.get_double("Module");
    pressure_angle = prm.get_double("Pressure angle");
    addendum = prm.get_double("Addendum");
    dedendum = prm.get_double("Dedendum");
    tooth_thickness = prm.get_double("Tooth thickness");
    fillet_radius = prm.get_double("Root fillet radius");
    tip_radius = prm.get_double("Tip radius");
    tooth_axis_angle = prm.get_double("Tooth axis angle");
    sector_teeth = prm.get_integer("Teeth in sector");
    require(diametral_pitch > 0. || module > 0., path + "Module", "set Diametral pitch or Module");
  }

  std::unique_ptr<const RigidSurface<2>>
  InvoluteGearParameters::create(const std::string &path) const
  {
    constexpr double                 degree = numbers::PI / 180.;
    const geometry::ToothProportions proportions
        = geometry::tooth_proportions(addendum, dedendum, tooth_thickness, fillet_radius);
    try
    {
      const auto gear = geometry::InvoluteGear::from_pitch_or_module(
          teeth, diametral_pitch, module, pressure_angle * degree, proportions);
      return std::make_unique<ChainSurface>(
          "involute gear",
          DieSurface::involute_gear(gear, tooth_axis_angle * degree, sector_teeth, tip_radius));
    }
    catch (const EntryError &e)
    {
      // the gear and the die-surface factory name the entry that failed
      throw InputError(path + e.entry() + ": " + e.what_is_wrong());
    }
    catch (const std::exception &e)
    {
      throw InputError(path.substr(0, path.size() - 1) + ": invalid gear (" + std::string(e.what())
                       + ")");
    }
  }
} // namespace ausroll::contact::surfaces

AUSROLL_REGISTER_DIE_SHAPE(
    2,
    ausroll::contact::surfaces::InvoluteGearParameters,
    "involute gear",
    "Involute gear",
    "an external involute spur gear (tooth flanks, root fillets, tip circle)")
