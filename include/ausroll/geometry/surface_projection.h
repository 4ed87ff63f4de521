/**
 * @file surface_projection.h
 * The one projection type of curves and surfaces (2D curve chains of curve_chain.h, the rigid die
 * surfaces of contact/rigid_surface.h).
 *
 * Conventions (hold for every curve and shape, 2D and 3D):
 * - The outward unit normal n points from the material (of the die) INTO the space where the
 *   workpiece is. Signed gap g = (x - x_proj) . n: positive outside (open), negative inside
 *   (penetration). Wherever a projection is returned, x = x_proj + g n holds exactly (also at
 *   edges, corners and ends, where n is +-(x - x_proj)/|x - x_proj|).
 * - Tangents: dim - 1 orthonormal unit vectors orthogonal to n.
 *   2D: t = n rotated by -90 degrees, t = (n_y, -n_x) (the direction of travel of a CurveChain,
 *   material on its right).
 *   3D: (t_1, t_2, n) is a right-handed orthonormal basis, t_1 x t_2 = n; t_1 is the first
 *   surface-coordinate direction where the shape has one (documented per shape).
 * - Curvatures: principal curvature along each tangent, positive for a convex surface (centre of
 *   curvature inside the material), negative for a concave one, 0 on flat parts, edges and
 *   corners.
 * - Surface coordinates: dim - 1 numbers naming the closest point on the surface (2D: arc length
 *   s along the chain; 3D: documented per shape, e.g. axial position and arc length).
 */
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <limits>

namespace ausroll::geometry
{
  /**
   * The closest point of a curve (2D) or a surface (3D) to a point x, with gap, normal, tangents,
   * curvatures and surface coordinates: what CurveChain::project() and every
   * contact::RigidSurface::project() return (all in the frame the curve or surface is given in,
   * the die's local frame for a die).
   */
  template <int dim>
  struct SurfaceProjection
  {
    /** False if no surface point lies within the requested search distance (other fields unset). */
    bool valid = false;
    /** Closest point x_proj of the surface. */
    dealii::Point<dim> point;
    /** Signed gap g = (x - x_proj) . n: > 0 open, < 0 penetration. */
    double gap = 0.0;
    /** Distance |x - x_proj| = |g|. */
    double distance = 0.0;
    /** Outward unit normal n (die -> workpiece). */
    dealii::Tensor<1, dim> normal;
    /** Orthonormal tangents (see the file documentation for their orientation). */
    std::array<dealii::Tensor<1, dim>, dim - 1> tangents;
    /** Principal curvature along each tangent (positive = convex die). */
    std::array<double, dim - 1> curvatures{};
    /** Surface coordinates of x_proj (2D: arc length s). */
    std::array<double, dim - 1> coordinates{};
    /**
     * True if x_proj lies on an edge, a corner or a joint between pieces of the surface (the
     * normal is then +-(x - x_proj)/|x - x_proj|).
     */
    bool at_edge = false;
    /** True if x_proj lies on the boundary of an open (finite) surface: a contact algorithm may
        release such points. */
    bool at_end = false;
    /**
     * Distance along the surface from x_proj to the nearest rim of the die's body (the border of
     * an open, finite surface as given, without any extension to infinity that keeps the contact
     * smooth): > 0 within, <= 0 at or beyond the rim; +infinity for a closed surface, an unbounded
     * one (flat, infinite plane, cylinder) and shapes that do not say (RigidDie::project() takes 0
     * where at_end is set). A point with a negative gap lies behind the die's body only if this is
     * positive: beyond a rim the sign of the gap says nothing about being inside the die.
     */
    double end_margin = std::numeric_limits<double>::infinity();
  };
} // namespace ausroll::geometry
