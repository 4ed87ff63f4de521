#include <ausroll/contact/surfaces/chain_surface.h>

namespace ausroll::contact::surfaces
{
  using dealii::Point;

  ChainSurface::ChainSurface(std::string name, geometry::CurveChain chain)
      : shape_name(std::move(name))
      , die(std::move(chain))
  {
  }

  SurfaceProjection<2> ChainSurface::project(const Point<2> &x, const double max_distance) const
  {
    return die.project(x, max_distance);
  }

  Point<2> ChainSurface::point_at(const std::array<double, 1> &coordinates) const
  {
    return die.point_at(coordinates[0]);
  }

  std::array<double, 1> ChainSurface::coordinate_periods() const
  {
    return {{die.is_closed() ? die.total_length() : 0.0}};
  }
} // namespace ausroll::contact::surfaces
