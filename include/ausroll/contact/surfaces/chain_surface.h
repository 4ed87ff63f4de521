/**
 * @file chain_surface.h
 * A 2D curve chain (geometry/curve_chain.h) as the RigidSurface<2> of a 2D die shape: what the
 * shapes flat, circle, polyline, arc line and involute gear create.
 */
#pragma once

#include <ausroll/contact/rigid_surface.h>
#include <ausroll/geometry/curve_chain.h>

#include <deal.II/base/point.h>

#include <array>
#include <limits>
#include <string>

namespace ausroll::contact::surfaces
{
  /**
   * A 2D curve chain (geometry::CurveChain) seen as a RigidSurface<2> (the interface the contact
   * code uses): the projection of the chain (arc length s as the surface coordinate); closed chains
   * have the period total_length().
   */
  class ChainSurface : public RigidSurface<2>
  {
  public:
    /** The chain @p chain under the shape name @p name (as in the `Shape` selection). */
    ChainSurface(std::string name, geometry::CurveChain chain);

    std::string name() const override { return shape_name; }

    SurfaceProjection<2> project(const dealii::Point<2> &x,
                                 double                  max_distance
                                 = std::numeric_limits<double>::infinity()) const override;

    dealii::Point<2> point_at(const std::array<double, 1> &coordinates) const override;

    std::array<double, 1> coordinate_periods() const override;

    /** The chain of segments. */
    const geometry::CurveChain &chain() const { return die; }

  private:
    std::string          shape_name;
    geometry::CurveChain die;
  };
} // namespace ausroll::contact::surfaces
