/**
 * @file rigid_die.h
 * A rigid die: surface, motion and friction law (one `Contact/Die N` subsection).
 */
#pragma once

#include <ausroll/contact/contact_parameters.h>
#include <ausroll/contact/die_motion.h>
#include <ausroll/contact/die_surface.h>
#include <ausroll/contact/friction_law.h>

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
   * A rigid die given by its surface (DieSurface, die coordinates) and its motion
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

    /** The die surface in die coordinates. */
    const DieSurface &die_surface() const { return *surface; }

    /** True if workpiece boundary @p id may touch this die. */
    bool is_candidate(const unsigned int id) const
    {
      return candidates.empty() || candidates.count(id) > 0;
    }

    const std::string                        name;            ///< `Name`
    const std::unique_ptr<const FrictionLaw> friction;        ///< `Friction` and its parameters
    const double                             search_distance; ///< `Search distance` (infinite if 0)

  private:
    std::unique_ptr<DieSurface> surface;
    std::unique_ptr<DieMotion>  motion;
    std::set<unsigned int>      candidates;
  };
} // namespace ausroll::contact
