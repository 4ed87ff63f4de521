/**
 * @file involute_gear.h
 * Die shape `involute gear` (subsection `Contact/Die N/Involute gear`): an external spur gear, or
 * a sector of it, with exact involute flanks.
 */
#pragma once

#include <ausroll/contact/surfaces/surface_factory.h>
#include <ausroll/geometry/curve_chain.h>
#include <ausroll/geometry/gear_entries.h>
#include <ausroll/geometry/involute_gear.h>

namespace ausroll::contact::surfaces
{
  /**
   * Subsection `Involute gear`: an involute_gear_chain(), gear centre at the die
   * origin, material inside; the tooth proportions as geometry::InvoluteGear (diametral pitch or
   * module, pressure angle, addendum, dedendum, tooth thickness, root fillet), tip rounds, the
   * direction of tooth 0 and an optional sector of teeth around it.
   */
  struct InvoluteGearParameters : public ShapeParameters<2>
  {
    /** The gear size entries (`Number of teeth`, `Diametral pitch`, `Module`, `Pressure angle`,
        `Addendum`, `Dedendum`; geometry/gear_entries.h). */
    geometry::GearSize size{57};
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

  /**
   * Single involute flank die (see geometry::CurveSegment::involute() for the parameters).
   */
  geometry::CurveChain involute_flank_chain(const dealii::Point<2> &base_center,
                                            double                  base_radius,
                                            double                  origin_angle,
                                            int                     unwind_sense,
                                            double                  roll_start,
                                            double                  roll_end);

  /**
   * External gear die with exact analytic flanks: root lands and tip lands (arcs), root fillets
   * (arcs), radial flank pieces below the base circle (lines) and involute flanks; gear centre
   * at the local origin, material inside (chain travelled clockwise).
   * With @p n_teeth = 0 (or the gear's number of teeth) the whole gear is built as a closed
   * chain with a tooth axis at polar angle @p tooth_axis_angle. Otherwise an open sector of
   * n_teeth teeth symmetric about @p tooth_axis_angle is built (tooth k at
   * tooth_axis_angle + ((n_teeth - 1)/2 - k) 2 pi/z), from the middle of the space before the
   * first tooth to the middle of the space after the last one.
   * With @p tip_round > 0 each tip corner is replaced by a circular arc of that radius tangent
   * to the involute flank and to the outside circle (centre at radius r_a - tip_round, at the
   * normal distance tip_round inside the flank: polar angle theta_h(r_a - tip_round) -
   * tip_round / r_b from the tooth axis); it must leave a tip land and meet the involute part.
   */
  geometry::CurveChain involute_gear_chain(const geometry::InvoluteGear &gear,
                                           double                        tooth_axis_angle = 0.0,
                                           unsigned int                  n_teeth = 0,
                                           double                        tip_round = 0.0);
} // namespace ausroll::contact::surfaces
