/**
 * @file circle.h
 * Die shape `circle` (subsection `Contact/Die N/Circle`): a roll, a round punch or a round hole.
 */
#pragma once

#include <ausroll/contact/surfaces/surface_factory.h>
#include <ausroll/geometry/curve_chain.h>

#include <deal.II/base/point.h>

namespace ausroll::contact::surfaces
{
  /**
   * Subsection `Circle`: full circle (`Center`, `Radius`), a circle_chain(): with
   * `Material inside` (a roll or punch) travelled clockwise with the normal outward, otherwise
   * (a hole) counter-clockwise with the normal towards the centre; s = 0 at centre + (r, 0).
   */
  struct CircleParameters : public ShapeParameters<2>
  {
    dealii::Point<2> center{0., 0.};         ///< `Center`
    double           radius = 1.;            ///< `Radius` (mm)
    bool             material_inside = true; ///< `Material inside`

    /** Declare the entries of subsection `Circle` (the caller has entered it). */
    static void                            declare_parameters(dealii::ParameterHandler &prm);
    void                                   parse(dealii::ParameterHandler &prm,
                                                 const std::string        &path,
                                                 const std::string        &input_directory) override;
    std::unique_ptr<const RigidSurface<2>> create(const std::string &path) const override;
  };

  /**
   * Full circle with @p center and @p radius, s = 0 at center + (radius, 0). With
   * @p material_inside (default; a die roll or round punch) it is travelled clockwise and the
   * normal points outward; otherwise (a round hole, concave) counter-clockwise with the normal
   * towards the centre.
   */
  geometry::CurveChain
  circle_chain(const dealii::Point<2> &center, double radius, bool material_inside = true);

} // namespace ausroll::contact::surfaces
