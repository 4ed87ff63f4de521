/**
 * @file flat.h
 * Die shape `flat` (subsection `Contact/Die N/Flat`): an infinite straight die.
 */
#pragma once

#include <ausroll/contact/surfaces/surface_factory.h>

#include <deal.II/base/point.h>

namespace ausroll::contact::surfaces
{
  /**
   * Subsection `Flat`: the infinite straight line through `Point` with the outward `Normal`
   * (out of the die, towards the workpiece). A DieSurface::flat() chain: travelled along
   * t = n rotated by -90 degrees, s = 0 at `Point`.
   */
  struct FlatParameters : public ShapeParameters<2>
  {
    dealii::Point<2> point{0., 0.};  ///< `Point`
    dealii::Point<2> normal{0., 1.}; ///< `Normal`

    /** Declare the entries of subsection `Flat` (the caller has entered it). */
    static void                            declare_parameters(dealii::ParameterHandler &prm);
    void                                   parse(dealii::ParameterHandler &prm,
                                                 const std::string        &path,
                                                 const std::string        &input_directory) override;
    std::unique_ptr<const RigidSurface<2>> create(const std::string &path) const override;
  };
} // namespace ausroll::contact::surfaces
