/**
 * @file flat.h
 * Die shape `flat` (subsection `Contact/Die N/Flat`): an infinite straight die.
 */
#pragma once

#include <ausroll/contact/surfaces/surface_factory.h>
#include <ausroll/geometry/curve_chain.h>

#include <deal.II/base/point.h>

#include <limits>

namespace ausroll::contact::surfaces
{
  /**
   * Subsection `Flat`: the infinite straight line through `Point` with the outward `Normal`
   * (out of the die, towards the workpiece). A flat_chain(): travelled along
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

  /**
   * Flat die through @p point with direction of travel @p direction, extending @p half_length
   * to each side of @p point (infinite by default). The workpiece side is to the left of
   * @p direction (n = direction rotated by +90 degrees); s = 0 at @p point for an infinite flat
   * and at point - half_length d for a finite one.
   */
  geometry::CurveChain flat_chain(const dealii::Point<2>     &point,
                                  const dealii::Tensor<1, 2> &direction,
                                  double half_length = std::numeric_limits<double>::infinity());

} // namespace ausroll::contact::surfaces
