/**
 * @file arc_line.h
 * Die shape `arc line` (subsection `Contact/Die N/Arc line`): a polyline whose interior corners
 * are rounded by tangent circular arcs.
 */
#pragma once

#include <ausroll/contact/surfaces/polyline.h>

#include <vector>

namespace ausroll::contact::surfaces
{
  /**
   * Subsection `Arc line`: a DieSurface::arc_line_composite() chain through the points (as
   * `Polyline`, ends extended to infinity) with a tangent fillet of `Fillet radii` at each
   * interior corner (one value for all, or one per corner; 0 keeps a sharp corner).
   */
  struct ArcLineParameters : public ShapeParameters<2>
  {
    DiePoints           outline;      ///< `Points`, `Points file`
    std::vector<double> fillet_radii; ///< `Fillet radii` (mm)

    /** Declare the entries of subsection `Arc line` (the caller has entered it). */
    static void                            declare_parameters(dealii::ParameterHandler &prm);
    void                                   parse(dealii::ParameterHandler &prm,
                                                 const std::string        &path,
                                                 const std::string        &input_directory) override;
    std::unique_ptr<const RigidSurface<2>> create(const std::string &path) const override;
  };
} // namespace ausroll::contact::surfaces
