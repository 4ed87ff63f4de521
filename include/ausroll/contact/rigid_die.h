/**
 * @file rigid_die.h
 * A rigid die: surface, motion and friction law (one `Contact/Die N` subsection).
 */
#pragma once

#include <ausroll/contact/contact_parameters.h>
#include <ausroll/contact/die_motion.h>
#include <ausroll/contact/die_surface.h>
#include <ausroll/contact/friction_law.h>
#include <ausroll/contact/rigid_surface.h>

#include <limits>
#include <memory>
#include <set>
#include <string>

namespace ausroll::contact
{
  /** Where a point lies relative to a die, in global coordinates. */
  struct DieProjection
  {
    bool                 valid = false; ///< false if beyond the search distance
    double               gap = 0.;      ///< signed gap, negative = penetration
    dealii::Point<2>     point;         ///< closest die point (global)
    dealii::Tensor<1, 2> normal;        ///< unit normal out of the die (global)
    dealii::Tensor<1, 2> tangent;       ///< unit tangent (global), normal rotated by -90 degrees
    double               s = 0.;        ///< curvilinear coordinate on the die (die frame)
    dealii::Point<2>     local_point;   ///< closest die point in die coordinates
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

    /**
     * Closest point of the die to @p x (die coordinates) within @p max_distance, with the arc
     * length s = coordinates[0] (a DieSurface chain answers itself, with its segment index).
     */
    Projection project(const dealii::Point<2> &x,
                       double max_distance = std::numeric_limits<double>::infinity()) const;

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
   * A rigid die given by its surface (a RigidSurface<2> of one of the shapes of
   * contact/surfaces/, die coordinates) and its motion
   * (DieMotion: pose as a function of pseudo-time), with the friction law of `Friction` and the
   * workpiece boundaries (`Candidate boundaries`) that may touch it.
   */
  class RigidDie
  {
  public:
    /** Build die @p index from its parameters. Throws InputError naming the entry. */
    RigidDie(const DieParameters &parameters, const unsigned int index);

    /** Project global point @p x onto the die in its pose at time @p t. */
    DieProjection project(const dealii::Point<2> &x, const double t) const;

    /** Global position at time @p t of the die point with die coordinates @p X. */
    dealii::Point<2> material_point(const dealii::Point<2> &X, const double t) const;

    /** Pose at time @p t. */
    DiePose pose(const double t) const { return motion->pose(t); }

    /** The planetary rolling motion of this die, or nullptr if it moves otherwise. */
    const RollingMotion *rolling_motion() const
    {
      return dynamic_cast<const RollingMotion *>(motion.get());
    }

    /** The die surface in die coordinates (the dimension-generic interface). */
    const RigidSurface<2> &surface() const { return *shape; }

    /** The die surface in die coordinates seen by its arc length s (the 2D contact code). */
    const DieProfile &die_surface() const { return profile; }

    /** True if workpiece boundary @p id may touch this die. */
    bool is_candidate(const unsigned int id) const
    {
      return candidates.empty() || candidates.count(id) > 0;
    }

    const std::string                        name;            ///< `Name`
    const std::unique_ptr<const FrictionLaw> friction;        ///< `Friction` and its parameters
    const double                             search_distance; ///< `Search distance` (infinite if 0)

  private:
    std::unique_ptr<const RigidSurface<2>> shape;
    DieProfile                             profile;
    std::unique_ptr<DieMotion>             motion;
    std::set<unsigned int>                 candidates;
  };
} // namespace ausroll::contact
