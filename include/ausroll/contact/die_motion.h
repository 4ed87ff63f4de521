/**
 * @file die_motion.h
 * Rigid motion of a die: the pose (rotation + translation) of the die's local frame at time t.
 *
 * Pose convention (2D, angles in radians, counter-clockwise positive):
 *
 *     x = c + R(theta) (X - X_ref),      X = X_ref + R(-theta) (x - c),
 *
 * with X a point in the die's LOCAL frame (where DieSurface is described), x the same material
 * point in the GLOBAL frame, X_ref the die's reference point in local coordinates (e.g. the roll
 * centre; the local origin by default), c the global position of the reference point and
 * R(theta) = [[cos, -sin], [sin, cos]]. Directions (normals, tangents) transform with R(theta)
 * alone. The velocity of a die-fixed point is dc/dt + dtheta/dt k x (x - c).
 */
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <cmath>
#include <functional>
#include <optional>

namespace ausroll::contact
{
  /** A scalar function of time (an angle, a feed distance, ...). */
  using TimeFunction = std::function<double(double)>;

  /** A vector-valued function of time (a displacement). */
  using VectorTimeFunction = std::function<dealii::Tensor<1, 2>(double)>;

  /**
   * Rigid placement of a die: x = c + R(theta) (X - X_ref) (see the file documentation).
   */
  class DiePose
  {
  public:
    /** Identity pose: local and global frames coincide. */
    DiePose() = default;

    /**
     * Pose with the reference point @p local_reference (local coordinates) placed at
     * @p reference_position (global) and the die rotated by @p angle (counter-clockwise).
     */
    DiePose(const dealii::Point<2> &reference_position,
            double                  angle,
            const dealii::Point<2> &local_reference = dealii::Point<2>());

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

  /**
   * Abstract motion of a rigid die: its pose at every time t. Velocities are provided by central
   * differences of the pose in time (step h = 1e-6 (1 + |t|)) unless a subclass overrides them.
   */
  class DieMotion
  {
  public:
    /** Virtual destructor. */
    virtual ~DieMotion() = default;

    /** Pose of the die at time @p t. */
    virtual DiePose pose(double t) const = 0;

    /** Global velocity at time @p t of the die-fixed point with local coordinates @p X. */
    virtual dealii::Tensor<1, 2> velocity(double t, const dealii::Point<2> &X) const;

    /** Angular velocity d theta / dt at time @p t (rad per time unit, counter-clockwise). */
    virtual double angular_velocity(double t) const;

    /**
     * Global displacement of the die-fixed point @p X between times @p t0 and @p t1:
     * pose(t1).to_global(X) - pose(t0).to_global(X).
     */
    dealii::Tensor<1, 2> displacement(double t0, double t1, const dealii::Point<2> &X) const;

  protected:
    /** Time step used for the central differences at time @p t. */
    static double difference_step(double t);
  };

  /** A die that does not move: the same pose at all times (identity by default). */
  class FixedPose : public DieMotion
  {
  public:
    /** Die held at @p pose. */
    explicit FixedPose(const DiePose &pose = DiePose());

    /** The fixed pose. */
    DiePose pose(double t) const override;

    /** Zero. */
    dealii::Tensor<1, 2> velocity(double t, const dealii::Point<2> &X) const override;

    /** Zero. */
    double angular_velocity(double t) const override;

  private:
    /** The pose. */
    DiePose fixed;
  };

  /**
   * Prescribed translation u(t) and rotation phi(t) about a pivot:
   *
   *     x(t) = p0 + u(t) + R(phi(t)) (X - P),
   *
   * with P the pivot in local coordinates and p0 its global position when u = 0 (by default
   * p0 = P: the local frame coincides with the global one at rest). Both functions are supplied
   * by the caller (e.g. from a load curve); an empty function counts as zero.
   */
  class PrescribedMotion : public DieMotion
  {
  public:
    /**
     * Motion with @p translation u(t) and @p rotation phi(t) (rad, counter-clockwise) about the
     * @p pivot P (local coordinates), whose rest position p0 equals P.
     */
    PrescribedMotion(VectorTimeFunction      translation,
                     TimeFunction            rotation,
                     const dealii::Point<2> &pivot = dealii::Point<2>());

    /** As above, with the pivot at global position @p pivot_rest_position when u = 0. */
    PrescribedMotion(VectorTimeFunction      translation,
                     TimeFunction            rotation,
                     const dealii::Point<2> &pivot,
                     const dealii::Point<2> &pivot_rest_position);

    /** Translation with constant @p velocity from the rest position (u = v t), no rotation. */
    static PrescribedMotion constant_velocity(const dealii::Tensor<1, 2> &velocity);

    /** Pose: c = p0 + u(t), theta = phi(t), X_ref = P. */
    DiePose pose(double t) const override;

  private:
    /** u(t). */
    VectorTimeFunction translation;
    /** phi(t). */
    TimeFunction rotation;
    /** Pivot P in local coordinates. */
    dealii::Point<2> pivot;
    /** Global position p0 of the pivot at rest. */
    dealii::Point<2> pivot_rest;
  };

  /**
   * Planetary rolling (NOFEAP thesis, section 4.1): the workpiece (pitch radius R_G, centre O_G)
   * does not rotate; the die (pitch radius R_D, local frame with the die centre at the origin)
   * revolves about O_G and spins about its own centre.
   *
   * With sigma = +1 (direction = counter-clockwise revolution) or -1 (clockwise):
   * - line of centres angle  psi(t) = psi_0 + sigma theta_G(t)   (polar angle of the die centre
   *   seen from O_G),
   * - centre distance        a(t)   = a_0 - f(t)                 (radial feed f towards O_G),
   * - die centre             c(t)   = O_G + a(t) (cos psi, sin psi),
   * - spin relative to the line of centres
   *                          theta_D(t) = (R_G / R_D) theta_G(t) + (1 - beta) theta_s(t),
   * - absolute die rotation  theta(t) = theta_0 + sigma (theta_G(t) + theta_D(t)).
   *
   * For beta = 1 (or theta_s = 0) this is rolling without slip of the die pitch circle on the
   * workpiece pitch circle: the die point at the pitch point O_G + R_G (cos psi, sin psi) has zero
   * velocity (the die's absolute rotation rate is (1 + R_G/R_D) times the revolution rate, as for
   * a coin rolling around another coin). The slip angle theta_s(t) adds a die spin that is not
   * matched by the revolution; the slip speed at the pitch point is then
   * R_D (1 - beta) d theta_s/dt; beta = 0 means that the whole prescribed theta_s is slip.
   * (A blended law theta_D = beta (R_G/R_D) theta_G + (1 - beta) theta_s' is obtained with
   * theta_s = theta_s' - (R_G/R_D) theta_G.)
   */
  class RollingMotion : public DieMotion
  {
  public:
    /** Data of a rolling motion; lengths in mm, angles in rad. */
    struct Data
    {
      /** Global centre O_G of the (non-rotating) workpiece. */
      dealii::Point<2> workpiece_center;
      /** Workpiece pitch radius R_G (> 0). */
      double workpiece_radius = 0.0;
      /** Die pitch radius R_D (> 0). */
      double die_radius = 0.0;
      /** Centre distance a_0 at zero feed; default R_G + R_D (pitch circles touching). */
      std::optional<double> initial_center_distance;
      /** Polar angle psi_0 of the die centre seen from O_G at theta_G = 0 (default: above). */
      double initial_line_angle = 0.5 * M_PI;
      /** Die rotation theta_0 at t = 0 (orientation of the die's local frame). */
      double initial_die_angle = 0.0;
      /** +1: the die centre revolves counter-clockwise about O_G; -1: clockwise. */
      int direction = 1;
      /** Rolling ratio beta: 1 = pure rolling, 0 = the whole slip angle is slip. */
      double beta = 1.0;
      /** Revolution angle theta_G(t) >= 0 (rad); empty = 0. */
      TimeFunction revolution_angle;
      /** Slip angle theta_s(t) (rad); empty = 0. */
      TimeFunction slip_angle;
      /** Radial feed f(t) of the die centre towards O_G (mm); empty = 0. */
      TimeFunction feed;
    };

    /** Rolling motion from @p data; throws ausroll::InputError for invalid data. */
    explicit RollingMotion(const Data &data);

    /** Pose: c = die_center(t), theta = theta_0 + sigma (theta_G + theta_D), X_ref = origin. */
    DiePose pose(double t) const override;

    /** Line of centres angle psi(t) = psi_0 + sigma theta_G(t). */
    double line_angle(double t) const;

    /** Centre distance a(t) = a_0 - f(t). */
    double center_distance(double t) const;

    /** Global die centre c(t). */
    dealii::Point<2> die_center(double t) const;

    /** Die spin relative to the line of centres, theta_D(t) (see the class documentation). */
    double spin_angle(double t) const;

    /** Pitch point O_G + R_G (cos psi, sin psi) on the workpiece pitch circle. */
    dealii::Point<2> pitch_point(double t) const;

    /** The data. */
    const Data &data() const { return d; }

  private:
    /** The data (with defaults filled in). */
    Data d;
    /** a_0. */
    double a0;
  };
} // namespace ausroll::contact
