/**
 * @file boundary_depth.h
 * Depth below the initial surface of the workpiece: the distance of a point to the exact curved
 * outline formed by chosen boundary faces of the coarse mesh and their manifolds.
 */
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/grid/manifold.h>
#include <deal.II/grid/tria.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace ausroll::geometry
{
  /**
   * The depth of a point below the initial surface: its distance to the nearest point of the
   * boundary faces with the given ids, on the exact surface their manifolds describe (the
   * involute of FlankManifold, the circles of the PolarManifold, the cylinder of
   * CylindricalManifold; straight or bilinear where the face is flat). The shortest distance is
   * measured along the normal of the outline at its foot (where the foot is inside a smooth face)
   * or to an edge or corner of the outline: the depth of `Phases/Carbon content`.
   *
   * Construction: every boundary face of the coarse (level-0) cells with one of the ids is
   * sampled through its manifold (get_intermediate_point() in 2D, get_new_point() with bilinear
   * weights in 3D; a face of the cells' TransfiniteInterpolationManifold, such as the flat end of
   * a cylinder, as the Coons patch of its edges' manifolds in 3D and straight in 2D) at
   * samples_per_edge + 1 points per face edge; the samples, the faces' manifolds (clones) and, per
   * face, the gap: the largest distance of a point of a sample interval (cell) from its nearest
   * sample (half a diagonal, measured through the manifold at the interval's centre, times 1.1 for
   * the curvature).
   *
   * depth(): the nearest sample gives an upper bound d; only faces whose nearest sample is
   * closer than d + gap can hold a nearer point. On these, from every sample that is a discrete
   * local minimum of the distance, the squared distance to the face point is minimised over the
   * neighbouring sample intervals in the face parameter by Brent's method (2D; in 3D by
   * alternating Brent minimisations in the two face parameters until the distance changes by
   * less than 1e-15 of the outline size). The face ends are samples, so a foot at an edge or
   * corner is exact.
   *
   * Accuracy: Brent locates the face parameter of the foot to about 1.5e-8 (half the digits of
   * a double); the squared distance is stationary there, so the distance error is quadratic in
   * it: below 1e-12 of the outline size for a foot inside a smooth face, and round-off at an
   * edge or corner. In 3D the alternating minimisation is exact after one sweep on the extruded
   * outlines (the cylinder and the extruded tooth: the distance separates in the chart
   * coordinates (r, z)); on a general doubly curved face it converges linearly. The statement
   * fails only if the samples miss a local minimum of the distance: a face whose radius of
   * curvature is below about its length / samples_per_edge.
   */
  template <int dim>
  class BoundaryDepth
  {
  public:
    /**
     * The outline of the boundary faces of @p triangulation's coarse cells with an id in
     * @p ids; an id without such a face is an InputError naming @p entry (for messages: the
     * entry that lists the ids). The triangulation's manifolds are cloned.
     */
    BoundaryDepth(const dealii::Triangulation<dim> &triangulation,
                  const std::vector<unsigned int>  &ids,
                  const std::string                &entry,
                  const unsigned int                samples_per_edge = 32);

    /** The point of the outline nearest to a given point, and the outline's normal there. */
    struct Foot
    {
      dealii::Point<dim>     point;         ///< on the outline
      dealii::Tensor<1, dim> inward_normal; ///< unit normal of its face, into the workpiece
      double                 distance = 0.; ///< depth() of the given point
    };

    /**
     * The foot of @p p on the outline (as depth() finds it) and the unit normal of the face
     * holding it, pointing into the workpiece (towards the face's coarse cell): from central
     * differences of the face's points in its parameter(s), accurate to about 1e-10 (at an edge
     * or corner of the outline: the normal of the face whose point is nearest).
     */
    Foot nearest(const dealii::Point<dim> &p) const;

    /** Distance of @p p to the outline (mm, >= 0; the same outside the workpiece). */
    double depth(const dealii::Point<dim> &p) const;

    /** Number of coarse faces of the outline. */
    unsigned int n_faces() const { return faces.size(); }

    /** Size of the outline (diagonal of the bounding box of its samples). */
    double size() const { return extent; }

  private:
    /** One coarse boundary face: its vertices, manifold and samples. */
    struct Face
    {
      std::vector<dealii::Point<dim>> vertices; ///< 2 (2D) or 4 (3D)
      /** Clone of the face's manifold (empty for a face of the cells' transfinite
          interpolation: then the Coons patch of the #edges). */
      std::unique_ptr<const dealii::Manifold<dim, dim>> manifold;
      /** 3D: the manifolds of the face's lines 0 to 3 (the Coons patch). */
      std::array<std::unique_ptr<const dealii::Manifold<dim, dim>>, 4> edges;
      std::vector<dealii::Point<dim>> samples; ///< (n+1)^(dim-1), u fastest
      double             gap = 0.; ///< largest distance of a face point from its nearest sample
      dealii::Point<dim> interior; ///< the centre of the face's coarse cell (inward side)
    };

    /** The face point at parameters (u, v) in [0, 1]^(dim-1) (v unused in 2D). */
    dealii::Point<dim> point(const Face &face, const double u, const double v) const;

    /** depth() of @p p; with @p foot_face the face and parameters of the nearest point. */
    double closest(const dealii::Point<dim> &p,
                   unsigned int             *foot_face,
                   double                   *foot_u,
                   double                   *foot_v) const;

    /** Smallest distance of @p p to @p face from its samples' distances @p d, refined from the
        local minima of @p d that can be nearer than @p bound (the best distance so far); the
        face parameters of that nearest point into @p foot_u, @p foot_v if given. */
    double refine(const Face                &face,
                  const dealii::Point<dim>  &p,
                  const std::vector<double> &d,
                  const double               bound,
                  double                    *foot_u = nullptr,
                  double                    *foot_v = nullptr) const;

    std::vector<Face> faces;
    unsigned int      n;           ///< sample intervals per face edge
    double            extent = 0.; ///< size()
  };
} // namespace ausroll::geometry
