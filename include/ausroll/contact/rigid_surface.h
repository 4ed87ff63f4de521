/**
 * @file rigid_surface.h
 * The dimension-generic interface of an analytic rigid die surface (2D curve or 3D surface),
 * given in the die's LOCAL frame. The die's pose(t) (DieMotion) maps it to global coordinates.
 *
 * Conventions (hold for every shape, 2D and 3D):
 * - The outward unit normal n points from the die material INTO the space where the workpiece
 *   is. Signed gap g = (x - x_proj) . n: positive outside the die (open), negative inside
 *   (penetration). Wherever a projection is returned, x = x_proj + g n holds exactly (also at
 *   edges, corners and ends, where n is +-(x - x_proj)/|x - x_proj|).
 * - Tangents: dim - 1 orthonormal unit vectors orthogonal to n.
 *   2D: t = n rotated by -90 degrees, t = (n_y, -n_x) (the direction of travel of a
 *   geometry::CurveChain, die material on its right).
 *   3D: (t_1, t_2, n) is a right-handed orthonormal basis, t_1 x t_2 = n; t_1 is the first
 *   surface-coordinate direction where the shape has one (documented per shape).
 * - Curvatures: principal curvature along each tangent, positive for a convex die (centre of
 *   curvature inside the die material), negative for a concave one, 0 on flat parts, edges and
 *   corners.
 * - Surface coordinates: dim - 1 numbers naming the closest point on the surface (2D: arc length
 *   s along the chain; 3D: documented per shape, e.g. axial position and arc length). They are
 *   continuous along the surface where the shape has a natural parametrisation.
 */
#pragma once

#include <ausroll/geometry/surface_projection.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <limits>
#include <stdexcept>
#include <string>

namespace ausroll::contact
{
  /** The projection on a die surface (geometry/surface_projection.h). */
  using geometry::SurfaceProjection;

  /**
   * An analytic rigid surface in the die's local frame. One class per shape; each shape has its
   * own `.prm` subsection and one factory line. See the file documentation for the conventions.
   */
  template <int dim>
  class RigidSurface
  {
  public:
    virtual ~RigidSurface() = default;

    /** Shape name as in the `.prm` selection (e.g. "circle", "torus"). */
    virtual std::string name() const = 0;

    /**
     * Closest point of the surface to @p x (local frame), with gap, normal, tangents, curvatures
     * and surface coordinates. If no surface point lies within @p max_distance the result has
     * valid == false.
     */
    virtual SurfaceProjection<dim> project(const dealii::Point<dim> &x,
                                           double                    max_distance
                                           = std::numeric_limits<double>::infinity()) const = 0;

    /**
     * The surface point with surface coordinates @p coordinates (the inverse of
     * SurfaceProjection::coordinates: point_at(project(x).coordinates) = project(x).point).
     * Coordinates outside the surface are wrapped where the coordinate is periodic (see
     * coordinate_periods()) and clamped to the surface otherwise. The 2D contact code uses it for
     * the stick point of a node that stops slipping: every 2D shape implements it; a shape
     * without it (the default) throws std::logic_error naming the shape.
     */
    virtual dealii::Point<dim> point_at(const std::array<double, dim - 1> &coordinates) const
    {
      (void)coordinates;
      throw std::logic_error(name() + ": point_at(surface coordinates) is not available");
    }

    /**
     * Period of each surface coordinate, 0 for a coordinate that is not periodic (2D: the total
     * length of a closed curve, 0 for an open one). Differences of a periodic coordinate are
     * taken modulo the period (slip distances along a closed die).
     */
    virtual std::array<double, dim - 1> coordinate_periods() const { return {}; }
  };
} // namespace ausroll::contact
