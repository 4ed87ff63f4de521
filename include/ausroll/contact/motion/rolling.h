/**
 * @file rolling.h
 * Die motion `rolling` (subsection `Contact/Die N/Motion/Rolling`): planetary rolling about the
 * workpiece centre (NOFEAP thesis, section 4.1).
 */
#pragma once

#include <ausroll/contact/die_motion.h>

#include <memory>
#include <optional>
#include <string>

namespace ausroll::contact
{
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

  /** Subsection `Motion/Rolling` (`Motion/Type = rolling`). */
  struct RollingMotionParameters : public MotionParameters
  {
    std::string workpiece_center = "0, 0"; ///< `Workpiece center` O_G (read by create())
    std::string axis = "0, 0, 1";          ///< `Axis` of the workpiece (3D; read by create_3d())
    double      workpiece_radius = 1.;     ///< `Workpiece rolling radius` R_G
    double      die_radius = 1.;           ///< `Die rolling radius` R_D
    double      center_distance = 0.;      ///< `Initial center distance` (0: R_G + R_D)
    double      line_angle = 90.;          ///< `Initial line angle` (degrees)
    int         direction = 1;             ///< `Direction` (+1 counter-clockwise, -1)
    double      beta = 1.;                 ///< `Rolling factor` beta (1 pure rolling)
    std::string revolution = "0";          ///< `Revolution angle` theta_G(t) (degrees)
    std::string slip = "0";                ///< `Slip angle` theta_s(t) (degrees)
    std::string feed = "0";                ///< `Feed` f(t) (mm)

    /** Declare the entries of subsection `Rolling` (the caller has entered it). */
    static void                   declare_parameters(dealii::ParameterHandler &prm);
    void                          parse(dealii::ParameterHandler &prm,
                                        const std::string        &path,
                                        const std::string        &input_directory) override;
    std::unique_ptr<DieMotion<2>> create_2d(const std::string &path) const override;
    std::unique_ptr<DieMotion<3>> create_3d(const std::string &path) const override;
  };
} // namespace ausroll::contact
