/**
 * @file involute_gear.h
 * Die shape `involute gear` (subsection `Contact/Die N/Involute gear`): an external spur gear, or
 * a sector of it, with exact involute flanks.
 */
#pragma once

#include <ausroll/contact/surfaces/surface_factory.h>

namespace ausroll::contact::surfaces
{
  /**
   * Subsection `Involute gear`: a DieSurface::involute_gear() chain, gear centre at the die
   * origin, material inside; the tooth proportions as geometry::InvoluteGear (diametral pitch or
   * module, pressure angle, addendum, dedendum, tooth thickness, root fillet), tip rounds, the
   * direction of tooth 0 and an optional sector of teeth around it.
   */
  struct InvoluteGearParameters : public ShapeParameters<2>
  {
    unsigned int teeth = 57;            ///< `Number of teeth`
    double       diametral_pitch = 8.5; ///< `Diametral pitch` (1/inch; 0: use Module)
    double       module = 0.;           ///< `Module` (mm)
    double       pressure_angle = 22.;  ///< `Pressure angle` (degrees)
    double       addendum = -1.;        ///< `Addendum` (mm; <0: 1 module)
    double       dedendum = -1.;        ///< `Dedendum` (mm; <0: 1.25 module)
    double       tooth_thickness = -1.; ///< `Tooth thickness` at the pitch circle (<0: half pitch)
    double       fillet_radius = 0.;    ///< `Root fillet radius` (mm)
    double       tip_radius = 0.;       ///< `Tip radius` (mm; 0: sharp tip corners)
    double       tooth_axis_angle = 0.; ///< `Tooth axis angle` (degrees)
    unsigned int sector_teeth = 0;      ///< `Teeth in sector` (0: whole gear)

    /** Declare the entries of subsection `Involute gear` (the caller has entered it). */
    static void                            declare_parameters(dealii::ParameterHandler &prm);
    void                                   parse(dealii::ParameterHandler &prm,
                                                 const std::string        &path,
                                                 const std::string        &input_directory) override;
    std::unique_ptr<const RigidSurface<2>> create(const std::string &path) const override;
  };
} // namespace ausroll::contact::surfaces
