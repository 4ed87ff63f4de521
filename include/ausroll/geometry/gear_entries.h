/**
 * @file gear_entries.h
 * The `.prm` entries that size an involute gear (teeth, diametral pitch or module, pressure angle,
 * addendum, dedendum), declared once for every subsection that describes a gear (the gear die
 * `Contact/Die N/Involute gear` and the workpiece `Geometry/Gear tooth`).
 */
#pragma once

#include <ausroll/geometry/involute_gear.h>

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace ausroll::geometry
{
  /**
   * Declare `Number of teeth` (default @p default_teeth, documented as @p teeth_documentation),
   * `Diametral pitch`, `Module`, `Pressure angle`, `Addendum` and `Dedendum` in the current
   * subsection of @p prm. Read them back with GearSize::parse().
   */
  void declare_gear_size_entries(dealii::ParameterHandler &prm,
                                 const std::string        &default_teeth,
                                 const std::string        &teeth_documentation);

  /**
   * The values of the gear size entries (declare_gear_size_entries()) of one subsection; the
   * gear is made from them with InvoluteGear::from_pitch_or_module() and ToothProportions
   * (negative addendum / dedendum: the module-based default).
   */
  struct GearSize
  {
    unsigned int teeth = 20;            ///< `Number of teeth` z
    double       diametral_pitch = 8.5; ///< `Diametral pitch` (teeth per inch; 0: use Module)
    double       module = 0.;           ///< `Module` m (mm), when Diametral pitch = 0
    double       pressure_angle = 22.;  ///< `Pressure angle` (degrees)
    double       addendum = -1.;        ///< `Addendum` (mm; negative: 1 module)
    double       dedendum = -1.;        ///< `Dedendum` (mm; negative: 1.25 module)

    /** Read the entries from the current subsection of @p prm. */
    void parse(const dealii::ParameterHandler &prm);
  };

  /**
   * The ToothProportions of the entries `Addendum`, `Dedendum` (negative: the module-based
   * default), `Tooth thickness` (not positive: half the circular pitch) and `Root fillet radius`.
   */
  ToothProportions tooth_proportions(double addendum,
                                     double dedendum,
                                     double pitch_tooth_thickness,
                                     double root_fillet_radius);
} // namespace ausroll::geometry
