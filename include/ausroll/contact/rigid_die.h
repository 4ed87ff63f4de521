/**
 * @file rigid_die.h
 * A rigid die: surface, motion and friction law (one `Contact/Die N` subsection).
 */
#pragma once

#include <ausroll/contact/contact_parameters.h>
#include <ausroll/contact/die_motion.h>
#include <ausroll/contact/friction_law.h>
#include <ausroll/contact/rigid_surface.h>

#include <algorithm>
#include <array>
#include <limits>
#include <memory>
#include <set>
#include <string>
#include <type_traits>

namespace ausroll::contact
{
  /** Where a point lies relative to a die, in global coordinates. */
  template <int dim>
  struct DieProjection
  {
    bool                   valid = false; ///< false if beyond the search distance
    double                 gap = 0.;      ///< signed gap, negative = penetration
    dealii::Point<dim>     point;         ///< closest die point (global)
    dealii::Tensor<1, dim> normal;        ///< unit normal out of the die (global)
    /** Unit tangents (global): 2D the normal rotated by -90 degrees; 3D (t_1, t_2, n)
        right-handed (rigid_surface.h). */
    std::array<dealii::Tensor<1, dim>, dim - 1> tangents;
    dealii::Tensor<1, dim>                      tangent;       ///< tangents[0]
    std::array<double, dim - 1>                 coordinates{}; ///< surface coordinates (die frame)
    double             s = 0.;      ///< coordinates[0] (2D: arc length on the die)
    dealii::Point<dim> local_point; ///< closest die point in die coordinates
    /** SurfaceProjection::end_margin (0 at an open end, at_end): how far the closest point lies
        within the rim of the die's body; +infinity on closed and unbounded dies. */
    double end_margin = std::numeric_limits<double>::infinity();
    /** How deep the point lies inside the die's body: min(-gap, end_margin), so not inside (<= 0)
        where it lies beyond the end of an open, finite die, whatever the sign of the gap. */
    double depth() const { return std::min(-gap, end_margin); }
  };

  /**
   * A 2D die surface (any RigidSurface<2>) seen by its arc length s, as the 2D contact code uses
   * it (stick points, slip along the die, closed dies): RigidDie::die_surface().
   */
  class DieProfile
  {
  public:
    /** View of @p surface (which must outlive the view). */
    explicit DieProfile(const RigidSurface<2> &surface)
        : surface(&surface)
    {
    }

    /** Closest point of the die to @p x (die coordinates) within @p max_distance, with the arc
        length s = coordinates[0]. */
    SurfaceProjection<2> project(const dealii::Point<2> &x,
                                 double                  max_distance
                                 = std::numeric_limits<double>::infinity()) const
    {
      return surface->project(x, max_distance);
    }

    /** Point at arc length @p s (wrapped on a closed die, clamped on an open one). */
    dealii::Point<2> point_at(const double s) const { return surface->point_at({{s}}); }

    /** Whether the die is a closed curve (s periodic). */
    bool is_closed() const { return surface->coordinate_periods()[0] > 0.; }

    /** Period of s on a closed die (its perimeter). */
    double total_length() const { return surface->coordinate_periods()[0]; }

  private:
    const RigidSurface<2> *surface;
  };

  /**
   * A rigid die given by its surface (a RigidSurface<dim> of one of the shapes of
   * contact/surfaces/, die coordinates: 2D shapes for dim = 2, 3D shapes for dim = 3, both
   * registered in surface_factory.h) and its motion (DieMotion<dim>: pose as a function of
   * pseudo-time), with the friction law of `Friction` and the workpiece boundaries (`Candidate
   * boundaries`) that may touch it.
   */
  template <int dim>
  class RigidDie
  {
  public:
    /**
     * Build die @p index from its parameters; @p friction hands the friction law what it needs
     * from the workpiece (the shear yield stress). Throws InputError naming the entry (also for a
     * `Shape` of the other dimension, or a shear law on an elastic workpiece).
     */
    RigidDie(const DieParameters   &parameters,
             const unsigned int     index,
             const FrictionContext &friction = FrictionContext());

    /** Project global point @p x onto the die in its pose at time @p t. */
    DieProjection<dim> project(const dealii::Point<dim> &x, const double t) const;

    /** Global position at time @p t of the die point with die coordinates @p X. */
    dealii::Point<dim> material_point(const dealii::Point<dim> &X, const double t) const;

    /** Pose at time @p t. */
    DiePose<dim> pose(const double t) const { return motion->pose(t); }

    /** The motion. */
    const DieMotion<dim> &die_motion() const { return *motion; }

    /** The planetary rolling motion of this die, or nullptr if it moves otherwise. */
    const RollingMotion<dim> *rolling_motion() const { return motion->as_rolling(); }

    /** The die surface in die coordinates (the dimension-generic interface). */
    const RigidSurface<dim> &surface() const { return *shape; }

    /** The die surface in die coordinates seen by its arc length s (the 2D contact code). */
    template <int d = dim, typename = std::enable_if_t<d == 2>>
    const DieProfile &die_surface() const
    {
      return *profile;
    }

    /** Let workpiece boundary @p id touch this die too (nothing if all boundaries may). */
    void add_candidate(const unsigned int id)
    {
      if (!candidates.empty())
        candidates.insert(id);
    }

    /** True if workpiece boundary @p id may touch this die. */
    bool is_candidate(const unsigned int id) const
    {
      return candidates.empty() || candidates.count(id) > 0;
    }

    const std::string                        name;            ///< `Name`
    const std::unique_ptr<const FrictionLaw> friction;        ///< `Friction` and its parameters
    const double                             search_distance; ///< `Search distance` (infinite if 0)

  private:
    std::unique_ptr<const RigidSurface<dim>> shape;
    std::unique_ptr<DieProfile>              profile; ///< 2D only
    std::unique_ptr<DieMotion<dim>>          motion;
    std::set<unsigned int>                   candidates;
  };
} // namespace ausroll::contact
