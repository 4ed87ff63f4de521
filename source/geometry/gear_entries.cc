#include <ausroll/geometry/gear_entries.h>

namespace ausroll::geometry
{
  using namespace dealii;

  void declare_gear_size_entries(ParameterHandler  &prm,
                                 const std::string &default_teeth,
                                 const std::string &teeth_documentation)
  {
    prm.declare_entry("Number of teeth", default_teeth, Patterns::Integer(3), teeth_documentation);
    prm.declare_entry("Diametral pitch",
                      "8.5",
                      Patterns::Double(0.),
                      "Teeth per inch of pitch diameter (0: use Module).");
    prm.declare_entry(
        "Module", "0", Patterns::Double(0.), "Module m (mm), used when Diametral pitch = 0.");
    prm.declare_entry(
        "Pressure angle", "22", Patterns::Double(0., 45.), "Pressure angle (degrees).");
    prm.declare_entry("Addendum", "-1", Patterns::Double(), "Addendum (mm); negative: 1 module.");
    prm.declare_entry(
        "Dedendum", "-1", Patterns::Double(), "Dedendum (mm); negative: 1.25 module.");
  }

  void GearSize::parse(const ParameterHandler &prm)
  {
    teeth = prm.get_integer("Number of teeth");
    diametral_pitch = prm.get_double("Diametral pitch");
    module = prm.get_double("Module");
    pressure_angle = prm.get_double("Pressure angle");
    addendum = prm.get_double("Addendum");
    dedendum = prm.get_double("Dedendum");
  }

  ToothProportions tooth_proportions(const double addendum,
                                     const double dedendum,
                                     const double pitch_tooth_thickness,
                                     const double root_fillet_radius)
  {
    ToothProportions proportions;
    if (addendum >= 0.)
      proportions.addendum = addendum;
    if (dedendum >= 0.)
      proportions.dedendum = dedendum;
    if (pitch_tooth_thickness > 0.)
      proportions.pitch_tooth_thickness = pitch_tooth_thickness;
    proportions.root_fillet_radius = root_fillet_radius;
    return proportions;
  }
} // namespace ausroll::geometry
