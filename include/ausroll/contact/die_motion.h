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
  template <int dim>
  using VectorTimeFunction = std::function<dealii::Tensor<1, dim>(double)>;

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

  /** A die that does not move: the same pose at all times (identity by default). */
  template <int dim>
  class FixedPose : public DieMotion<dim>
  {
  public:
    /** Die held at @p pose. */
    explicit FixedPose(const DiePose<dim> &pose = DiePose<dim>());

    /** The fixed pose. */
    DiePose<dim> pose(double t) const override;

    /** Zero. */
    dealii::Tensor<1, dim> velocity(double t, const dealii::Point<dim> &X) const override;

    /** Zero. */
    double angular_velocity(double t) const override;

  private:
    /** The pose. */
    DiePose<dim> fixed;
  };

  /**
   * Prescribed translation u(t) and rotation phi(t) about a pivot (3D: about an axis through the
   * pivot):
   *
   *     x(t) = p0 + u(t) + R(phi(t)) (X - P),
   *
   * with P the pivot in local coordinates and p0 its global position when u = 0 (by default
   * p0 = P: the local frame coincides with the global one at rest). Both functions are supplied
   * by the caller (e.g. from a load curve); an empty function counts as zero.
   */
  template <int dim>
  class PrescribedMotion : public DieMotion<dim>
  {
  public:
    /**
     * Motion with @p translation u(t) and @p rotation phi(t) (rad, counter-clockwise) about the
     * @p pivot P (local coordinates), whose rest position p0 equals P.
     */
    PrescribedMotion(VectorTimeFunction<dim>   translation,
                     TimeFunction              rotation,
                     const dealii::Point<dim> &pivot = dealii::Point<dim>());

    /**
     * As above, with the pivot at global position @p pivot_rest_position when u = 0, rotating
     * about @p axis (3D; zero: e_z; ignored in 2D).
     */
    PrescribedMotion(VectorTimeFunction<dim>       translation,
                     TimeFunction                  rotation,
                     const dealii::Point<dim>     &pivot,
                     const dealii::Point<dim>     &pivot_rest_position,
                     const dealii::Tensor<1, dim> &axis = dealii::Tensor<1, dim>());

    /** Translation with constant @p velocity from the rest position (u = v t), no rotation. */
    static PrescribedMotion constant_velocity(const dealii::Tensor<1, dim> &velocity);

    /** Pose: c = p0 + u(t), theta = phi(t) about the axis, X_ref = P. */
    DiePose<dim> pose(double t) const override;

  private:
    /** u(t). */
    VectorTimeFunction<dim> translation;
    /** phi(t). */
    TimeFunction rotation;
    /** Pivot P in local coordinates. */
    dealii::Point<dim> pivot;
    /** Global position p0 of the pivot at rest. */
    dealii::Point<dim> pivot_rest;
    /** Rotation axis (3D). */
    dealii::Tensor<1, dim> axis;
  };

  /**
   * Planetary rolling (NOFEAP thesis, section 4.1): the workpiece (pitch radius R_G, centre O_G)
   * does not rotate; the die (pitch radius R_D, local frame with the die centre at the origin)
   * revolves about O_G and spins about its own centre. In 3D the workpiece axis is the line
   * through O_G along the unit vector a (`axis`, e_z by default), the die axis is parallel to it
   * through the die centre, and the motion below takes place in the plane orthogonal to a, with
   * polar angles measured from e_1 (`reference`, its part orthogonal to a; by default
   * Frame3D::perpendicular(a), e_x for a = e_z) towards e_2 = a x e_1. With a = e_z this is the 2D
   * motion of the (x, y) plane, z unchanged.
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
  template <int dim>
  class RollingMotion : public DieMotion<dim>
  {
  public:
    /** Data of a rolling motion; lengths in mm, angles in rad. */
    struct Data
    {
      /** Global centre O_G of the (non-rotating) workpiece (3D: a point of its axis). */
      dealii::Point<dim> workpiece_center;
      /** 3D: direction a of the workpiece axis (zero: e_z). Ignored in 2D. */
      dealii::Tensor<1, dim> axis;
      /** 3D: direction of polar angle 0 (zero: Frame3D::perpendicular(a)). Ignored in 2D. */
      dealii::Tensor<1, dim> reference;
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
    DiePose<dim> pose(double t) const override;

    /** This motion. */
    const RollingMotion<dim> *as_rolling() const override { return this; }

    /** Line of centres angle psi(t) = psi_0 + sigma theta_G(t). */
    double line_angle(double t) const;

    /** Centre distance a(t) = a_0 - f(t). */
    double center_distance(double t) const;

    /** Global die centre c(t). */
    dealii::Point<dim> die_center(double t) const;

    /** Die spin relative to the line of centres, theta_D(t) (see the class documentation). */
    double spin_angle(double t) const;

    /** Pitch point O_G + R_G (cos psi, sin psi) on the workpiece pitch circle. */
    dealii::Point<dim> pitch_point(double t) const;

    /** The data. */
    const Data &data() const { return d; }

  private:
    /** The point O_G + r (cos psi e_1 + sin psi e_2) (2D: e_1 = x, e_2 = y). */
    dealii::Point<dim> polar_point(double r, double psi) const;

    /** The data (with defaults filled in). */
    Data d;
    /** a_0. */
    double a0;
    /** 3D: the in-plane basis e_1, e_2 (unused in 2D). */
    dealii::Tensor<1, dim> e1, e2;
  };
} // namespace ausroll::contact
