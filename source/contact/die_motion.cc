/**
 * @file die_motion.cc
 * Implementation of die poses and die motions (see die_motion.h for the conventions).
 */
#include <ausroll/contact/die_motion.h>
#include <ausroll/core/exceptions.h>

#include <cmath>

namespace ausroll::contact
{
  using dealii::Point;
  using dealii::Tensor;

  namespace
  {
    /** Value of @p f at @p t, or 0 for an empty function. */
    double evaluate(const TimeFunction &f, const double t)
    {
      return f ? f(t) : 0.0;
    }
  } // namespace

  // ------------------------------------------------------------------ DiePose

  DiePose::DiePose(const Point<2> &reference_position,
                   const double    angle,
                   const Point<2> &local_reference)
      : c(reference_position)
      , theta(angle)
      , cos_theta(std::cos(angle))
      , sin_theta(std::sin(angle))
      , X_ref(local_reference)
  {
  }

  Point<2> DiePose::to_global(const Point<2> &X) const
  {
    return c + rotate_vector_to_global(X - X_ref);
  }

  Point<2> DiePose::to_local(const Point<2> &x) const
  {
    return X_ref + rotate_vector_to_local(x - c);
  }

  Tensor<1, 2> DiePose::rotate_vector_to_global(const Tensor<1, 2> &v) const
  {
    Tensor<1, 2> r;
    r[0] = cos_theta * v[0] - sin_theta * v[1];
    r[1] = sin_theta * v[0] + cos_theta * v[1];
    return r;
  }

  Tensor<1, 2> DiePose::rotate_vector_to_local(const Tensor<1, 2> &v) const
  {
    Tensor<1, 2> r;
    r[0] = cos_theta * v[0] + sin_theta * v[1];
    r[1] = -sin_theta * v[0] + cos_theta * v[1];
    return r;
  }

  // ------------------------------------------------------------------ DieMotion

  double DieMotion::difference_step(const double t)
  {
    return 1e-6 * (1.0 + std::abs(t));
  }

  Tensor<1, 2> DieMotion::velocity(const double t, const Point<2> &X) const
  {
    const double h = difference_step(t);
    return (pose(t + h).to_global(X) - pose(t - h).to_global(X)) / (2.0 * h);
  }

  double DieMotion::angular_velocity(const double t) const
  {
    const double h = difference_step(t);
    return (pose(t + h).angle() - pose(t - h).angle()) / (2.0 * h);
  }

  Tensor<1, 2> DieMotion::displacement(const double t0, const double t1, const Point<2> &X) const
  {
    return pose(t1).to_global(X) - pose(t0).to_global(X);
  }

  // ------------------------------------------------------------------ FixedPose

  FixedPose::FixedPose(const DiePose &pose)
      : fixed(pose)
  {
  }

  DiePose FixedPose::pose(const double) const
  {
    return fixed;
  }

  Tensor<1, 2> FixedPose::velocity(const double, const Point<2> &) const
  {
    return Tensor<1, 2>();
  }

  double FixedPose::angular_velocity(const double) const
  {
    return 0.0;
  }

  // ------------------------------------------------------------------ PrescribedMotion

  PrescribedMotion::PrescribedMotion(VectorTimeFunction translation,
                                     TimeFunction       rotation,
                                     const Point<2>    &pivot)
      : PrescribedMotion(std::move(translation), std::move(rotation), pivot, pivot)
  {
  }

  PrescribedMotion::PrescribedMotion(VectorTimeFunction translation,
                                     TimeFunction       rotation,
                                     const Point<2>    &pivot,
                                     const Point<2>    &pivot_rest_position)
      : translation(std::move(translation))
      , rotation(std::move(rotation))
      , pivot(pivot)
      , pivot_rest(pivot_rest_position)
  {
  }

  PrescribedMotion PrescribedMotion::constant_velocity(const Tensor<1, 2> &velocity)
  {
    return PrescribedMotion([velocity](const double t) { return velocity * t; }, TimeFunction());
  }

  DiePose PrescribedMotion::pose(const double t) const
  {
    const Tensor<1, 2> u = translation ? translation(t) : Tensor<1, 2>();
    return DiePose(pivot_rest + u, evaluate(rotation, t), pivot);
  }

  // ------------------------------------------------------------------ RollingMotion

  RollingMotion::RollingMotion(const Data &data)
      : d(data)
      , a0(data.initial_center_distance.value_or(data.workpiece_radius + data.die_radius))
  {
    const std::string where = "Rolling motion";
    require(d.workpiece_radius > 0.0, where, "the workpiece pitch radius must be positive");
    require(d.die_radius > 0.0, where, "the die pitch radius must be positive");
    require(a0 > 0.0, where, "the initial centre distance must be positive");
    require(d.direction == 1 || d.direction == -1, where, "the direction must be +1 or -1");
    require(d.beta >= 0.0 && d.beta <= 1.0, where, "the rolling ratio beta must lie in [0, 1]");
  }

  double RollingMotion::line_angle(const double t) const
  {
    return d.initial_line_angle + d.direction * evaluate(d.revolution_angle, t);
  }

  double RollingMotion::center_distance(const double t) const
  {
    return a0 - evaluate(d.feed, t);
  }

  Point<2> RollingMotion::die_center(const double t) const
  {
    const double psi = line_angle(t);
    const double a = center_distance(t);
    return d.workpiece_center + Point<2>(a * std::cos(psi), a * std::sin(psi));
  }

  double RollingMotion::spin_angle(const double t) const
  {
    return d.workpiece_radius / d.die_radius * evaluate(d.revolution_angle, t)
           + (1.0 - d.beta) * evaluate(d.slip_angle, t);
  }

  Point<2> RollingMotion::pitch_point(const double t) const
  {
    const double psi = line_angle(t);
    return d.workpiece_center
           + Point<2>(d.workpiece_radius * std::cos(psi), d.workpiece_radius * std::sin(psi));
  }

  DiePose RollingMotion::pose(const double t) const
  {
    const double theta
        = d.initial_die_angle + d.direction * (evaluate(d.revolution_angle, t) + spin_angle(t));
    return DiePose(die_center(t), theta);
  }
} // namespace ausroll::contact
