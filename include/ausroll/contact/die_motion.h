/**
 * @file die_motion.h
 * Rigid motion of a die: the pose (rotation + translation) of the die's local frame at time t,
 * in 2D and 3D (DiePose<dim>, DieMotion<dim>).
 *
 * Pose convention (angles in radians, counter-clockwise positive about the axis):
 *
 *     x = c + R(theta) (X - X_ref),      X = X_ref + R(-theta) (x - c),
 *
 * with X a point in the die's LOCAL frame (where the RigidSurface is described), x the same
 * material point in the GLOBAL frame, X_ref the die's reference point in local coordinates (e.g.
 * the roll centre; the local origin by default), c the global position of the reference point.
 * - 2D: R(theta) = [[cos, -sin], [sin, cos]] (rotation about the out-of-plane axis k).
 * - 3D: R(theta) the rotation by theta about the unit axis a (right-hand rule; Rodrigues:
 *   R = cos I + sin [a]x + (1 - cos) a (x) a); a = e_z by default, so that a 3D pose with
 *   a = e_z acts on (x, y) as the 2D pose and leaves z unchanged.
 * Directions (normals, tangents) transform with R(theta) alone. The velocity of a die-fixed point
 * is dc/dt + dtheta/dt a x (x - c) (a = k in 2D).
 *
 * The kinds of motion (`Contact/Die N/Motion/Type`) are registered (core/registry.h): one file
 * pair per kind in contact/motion/ (fixed.h, prescribed.h, rolling.h) with its DieMotion<dim>
 * and its MotionParameters (own subsection of `Motion`), AUSROLL_REGISTER_DIE_MOTION at the end
 * of its `.cc`.
 */
#pragma once

#include <ausroll/core/registry.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <string>

namespace ausroll::contact
{
  /** A scalar function of time (an angle, a feed distance, ...). */
  using TimeFunction = std::function<double(double)>;

  /** A vector-valued function of time (a displacement). */
  template <int dim>
  using VectorTimeFunction = std::function<dealii::Tensor<1, dim>(double)>;

  /** Value of @p f at @p t, or 0 for an empty function. */
  inline double value_or_zero(const TimeFunction &f, const double t)
  {
    return f ? f(t) : 0.0;
  }

  template <int dim>
  class RollingMotion;

  /** Rigid placement of a die: x = c + R(theta) (X - X_ref) (see the file documentation). */
  template <int dim>
  class DiePose;

  /** 2D pose: rotation by theta about the out-of-plane axis. */
  template <>
  class DiePose<2>
  {
  public:
    /** Identity pose: local and global frames coincide. */
    DiePose() = default;

    /**
     * Pose with the reference point @p local_reference (local coordinates) placed at
     * @p reference_position (global) and the die rotated by @p angle (counter-clockwise).
     * @p axis is ignored (2D: always the out-of-plane axis).
     */
    DiePose(const dealii::Point<2>     &reference_position,
            double                      angle,
            const dealii::Point<2>     &local_reference = dealii::Point<2>(),
            const dealii::Tensor<1, 2> &axis = dealii::Tensor<1, 2>());

    /** Global position x of the die point with local coordinates @p X. */
    dealii::Point<2> to_global(const dealii::Point<2> &X) const;

    /** Local coordinates X of the global point @p x. */
    dealii::Point<2> to_local(const dealii::Point<2> &x) const;

    /** Rotate a local direction (normal, tangent, force) into the global frame: R(theta) v. */
    dealii::Tensor<1, 2> rotate_vector_to_global(const dealii::Tensor<1, 2> &v) const;

    /** Rotate a global direction into the local frame: R(-theta) v. */
    dealii::Tensor<1, 2> rotate_vector_to_local(const dealii::Tensor<1, 2> &v) const;

    /** Global position c of the reference point. */
    const dealii::Point<2> &reference_position() const { return c; }

    /** Rotation angle theta (rad, counter-clockwise). */
    double angle() const { return theta; }

    /** Reference point X_ref in local coordinates. */
    const dealii::Point<2> &local_reference() const { return X_ref; }

  private:
    /** Global position of the reference point. */
    dealii::Point<2> c;
    /** Rotation angle (rad). */
    double theta = 0.0;
    /** cos(theta), sin(theta). */
    double cos_theta = 1.0, sin_theta = 0.0;
    /** Reference point in local coordinates. */
    dealii::Point<2> X_ref;
  };

  /** 3D pose: rotation by theta about the unit axis a (e_z by default). */
  template <>
  class DiePose<3>
  {
  public:
    /** Identity pose. */
    DiePose();

    /**
     * Pose with @p local_reference placed at @p reference_position and the die rotated by
     * @p angle about @p axis (nonzero; normalised; zero means e_z).
     */
    DiePose(const dealii::Point<3>     &reference_position,
            double                      angle,
            const dealii::Point<3>     &local_reference = dealii::Point<3>(),
            const dealii::Tensor<1, 3> &axis = dealii::Tensor<1, 3>());

    dealii::Point<3>     to_global(const dealii::Point<3> &X) const;
    dealii::Point<3>     to_local(const dealii::Point<3> &x) const;
    dealii::Tensor<1, 3> rotate_vector_to_global(const dealii::Tensor<1, 3> &v) const;
    dealii::Tensor<1, 3> rotate_vector_to_local(const dealii::Tensor<1, 3> &v) const;

    const dealii::Point<3> &reference_position() const { return c; }
    /** Rotation angle theta about axis() (rad, right-hand rule). */
    double angle() const { return theta; }
    /** Unit rotation axis a. */
    const dealii::Tensor<1, 3> &axis() const { return a; }
    const dealii::Point<3>     &local_reference() const { return X_ref; }

  private:
    dealii::Point<3>     c;
    double               theta = 0.0;
    dealii::Tensor<1, 3> a;
    dealii::Tensor<2, 3> R; ///< R(theta) about a
    dealii::Point<3>     X_ref;
  };

  /**
   * Abstract motion of a rigid die: its pose at every time t. Velocities are provided by central
   * differences of the pose in time (step h = 1e-6 (1 + |t|)) unless a subclass overrides them.
   */
  template <int dim>
  class DieMotion
  {
  public:
    /** Virtual destructor. */
    virtual ~DieMotion() = default;

    /** Pose of the die at time @p t. */
    virtual DiePose<dim> pose(double t) const = 0;

    /** Global velocity at time @p t of the die-fixed point with local coordinates @p X. */
    virtual dealii::Tensor<1, dim> velocity(double t, const dealii::Point<dim> &X) const;

    /** Angular velocity d theta / dt at time @p t (rad per time unit, about the pose's axis). */
    virtual double angular_velocity(double t) const;

    /**
     * Global displacement of the die-fixed point @p X between times @p t0 and @p t1:
     * pose(t1).to_global(X) - pose(t0).to_global(X).
     */
    dealii::Tensor<1, dim> displacement(double t0, double t1, const dealii::Point<dim> &X) const;

    /** This motion as a planetary rolling motion, or nullptr if it is another kind. */
    virtual const RollingMotion<dim> *as_rolling() const { return nullptr; }

  protected:
    /** Time step used for the central differences at time @p t. */
    static double difference_step(double t);
  };

  /**
   * The parameters of one kind of die motion: the entries of its own subsection
   * `Contact/Die N/Motion/<Subsection>` (none for `fixed`), registered in MotionRegistry with
   * AUSROLL_REGISTER_DIE_MOTION at the end of the motion's own `.cc` (contact/motion/). Entries
   * whose reading depends on the dimension of the run (points, the Translation's components) are
   * read by create().
   */
  class MotionParameters
  {
  public:
    virtual ~MotionParameters() = default;

    /** Read the motion's subsection (entered by the caller; @p path its full path with a
        trailing slash, "Contact/Die 0/Motion/Rolling/"). */
    virtual void parse(dealii::ParameterHandler &prm,
                       const std::string        &path,
                       const std::string        &input_directory)
        = 0;

    /** The motion in a 2D run; InputError naming the entry under @p path. */
    virtual std::unique_ptr<DieMotion<2>> create_2d(const std::string &path) const = 0;

    /** The motion in a 3D run; InputError naming the entry under @p path. */
    virtual std::unique_ptr<DieMotion<3>> create_3d(const std::string &path) const = 0;
  };

  /** The registry of the die motions (`Contact/Die N/Motion/Type`). */
  using MotionRegistry = Registry<MotionParameters>;

  /** The motion of @p parameters in a run of dimension @p dim (create_2d() or create_3d()). */
  template <int dim>
  std::unique_ptr<DieMotion<dim>> create_motion(const MotionParameters &parameters,
                                                const std::string      &path)
  {
    if constexpr (dim == 2)
      return parameters.create_2d(path);
    else
      return parameters.create_3d(path);
  }

  /**
   * A scalar function of t parsed from @p expression (variable t, constant pi) and multiplied by
   * @p scale; InputError naming @p entry if it cannot be parsed or (at t = 0 and whenever it is
   * evaluated later) its value is not finite.
   */
  TimeFunction
  parse_time_function(const std::string &expression, const std::string &entry, double scale = 1.);

  /** The point entry @p text of @p dim coordinates (3D also "x, y": z = 0, so that the 2D
      defaults serve); InputError naming @p entry. */
  template <int dim>
  dealii::Point<dim> parse_die_point(const std::string &text, const std::string &entry);

  /**
   * The motion entries that moved into a motion subsection (before: one flat list in
   * `Contact/Die N/Motion`): old full path -> new full path(s), added to @p moved, for the error
   * message an old `.prm` file gets; @p motion_path is "Contact/Die N/Motion/".
   */
  void add_moved_motion_entries(const std::string                  &motion_path,
                                std::map<std::string, std::string> &moved);
} // namespace ausroll::contact

/** Register the die-motion parameters @p Class (see AUSROLL_REGISTER). */
#define AUSROLL_REGISTER_DIE_MOTION(Class, name, subsection, description) \
  AUSROLL_REGISTER(::ausroll::contact::MotionParameters, Class, name, subsection, description)
