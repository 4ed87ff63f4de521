/**
 * @file flank_manifold.cc
 * Chart manifold of an involute flank (see flank_manifold.h).
 */
#include <ausroll/geometry/flank_manifold.h>

#include <cmath>

namespace ausroll::geometry
{
  using namespace dealii;

  FlankManifold::FlankManifold(const InvoluteGear &gear,
                               const FlankSide     side,
                               const double        axis_angle)
      : ChartManifold<2, 2, 1>()
      , gear(gear)
      , side(side)
      , axis_angle(axis_angle)
  {
  }

  std::unique_ptr<Manifold<2, 2>> FlankManifold::clone() const
  {
    return std::make_unique<FlankManifold>(gear, side, axis_angle);
  }

  Point<1> FlankManifold::pull_back(const Point<2> &space_point) const
  {
    return Point<1>(space_point.norm());
  }

  Point<2> FlankManifold::push_forward(const Point<1> &chart_point) const
  {
    const Point<2> q = gear.flank_point(chart_point[0], side);
    const double   c = std::cos(axis_angle), s = std::sin(axis_angle);
    return Point<2>(c * q[0] - s * q[1], s * q[0] + c * q[1]);
  }

  DerivativeForm<1, 1, 2> FlankManifold::push_forward_gradient(const Point<1> &chart_point) const
  {
    // theta(r) = theta_h(r) (positive flank) with d theta / dr = -u / r for r > r_b (u the roll
    // angle), 0 below: dP/dr = e_r + r theta' e_theta = e_r - u e_theta.
    const double            r = chart_point[0];
    const double            u = gear.roll_angle_at(r);
    const double            sign = side == FlankSide::positive ? 1.0 : -1.0;
    const double            phi = axis_angle + sign * gear.half_thickness_angle(r);
    const double            dphi = -sign * u;
    DerivativeForm<1, 1, 2> d;
    d[0][0] = std::cos(phi) - dphi * std::sin(phi);
    d[1][0] = std::sin(phi) + dphi * std::cos(phi);
    return d;
  }

  double FlankManifold::angular_distance(const Point<2> &p) const
  {
    const double r = p.norm();
    const double sign = side == FlankSide::positive ? 1.0 : -1.0;
    const double phi = std::atan2(p[1], p[0]) - axis_angle;
    return r * std::remainder(phi - sign * gear.half_thickness_angle(r), 2.0 * M_PI);
  }

  ExtrudedFlankManifold::ExtrudedFlankManifold(const InvoluteGear &gear,
                                               const FlankSide     side,
                                               const double        axis_angle)
      : ChartManifold<3, 3, 2>()
      , flank(gear, side, axis_angle)
      , gear(gear)
      , side(side)
      , axis_angle(axis_angle)
  {
  }

  std::unique_ptr<Manifold<3, 3>> ExtrudedFlankManifold::clone() const
  {
    return std::make_unique<ExtrudedFlankManifold>(gear, side, axis_angle);
  }

  Point<2> ExtrudedFlankManifold::pull_back(const Point<3> &space_point) const
  {
    return Point<2>(std::hypot(space_point[0], space_point[1]), space_point[2]);
  }

  Point<3> ExtrudedFlankManifold::push_forward(const Point<2> &chart_point) const
  {
    const Point<2> q = flank.push_forward(Point<1>(chart_point[0]));
    return Point<3>(q[0], q[1], chart_point[1]);
  }

  DerivativeForm<1, 2, 3>
  ExtrudedFlankManifold::push_forward_gradient(const Point<2> &chart_point) const
  {
    const DerivativeForm<1, 1, 2> d2 = flank.push_forward_gradient(Point<1>(chart_point[0]));
    DerivativeForm<1, 2, 3>       d;
    d[0][0] = d2[0][0];
    d[1][0] = d2[1][0];
    d[2][1] = 1.;
    return d;
  }

  double ExtrudedFlankManifold::angular_distance(const Point<3> &p) const
  {
    return flank.angular_distance(Point<2>(p[0], p[1]));
  }
} // namespace ausroll::geometry
