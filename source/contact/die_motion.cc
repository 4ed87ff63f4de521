/**
 * @file die_motion.cc
 * Implementation of die poses and die motions (see die_motion.h for the conventions).
 */
#include <ausroll/contact/die_motion.h>
#include <ausroll/contact/surfaces/frame_3d.h>
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

  DiePose<2>::DiePose(const Point<2> &reference_position,
                      const double    angle,
                      const Point<2> &local_reference,
                      const Tensor<1, 2> &)
      : c(reference_position)
      , theta(angle)
      , cos_theta(std::cos(angle))
      , sin_theta(std::sin(angle))
      , X_ref(local_reference)
  {
  }

  Point<2> DiePose<2>::to_global(const Point<2> &X) const
  {
    return c + rotate_vector_to_global(X - X_ref);
  }

  Point<2> DiePose<2>::to_local(const Point<2> &x) const
  {
    return X_ref + rotate_vector_to_local(x - c);
  }

  Tensor<1, 2> DiePose<2>::rotate_vector_to_global(const Tensor<1, 2> &v) const
  {
    Tensor<1, 2> r;
    r[0] = cos_theta * v[0] - sin_theta * v[1];
    r[1] = sin_theta * v[0] + cos_theta * v[1];
    return r;
  }

  Tensor<1, 2> DiePose<2>::rotate_vector_to_local(const Tensor<1, 2> &v) const
  {
    Tensor<1, 2> r;
    r[0] = cos_theta * v[0] + sin_theta * v[1];
    r[1] = -sin_theta * v[0] + cos_theta * v[1];
    return r;
  }

  DiePose<3>::DiePose()
      : DiePose(Point<3>(), 0.0)
  {
  }

  DiePose<3>::DiePose(const Point<3>     &reference_position,
                      const double        angle,
                      const Point<3>     &local_reference,
                      const Tensor<1, 3> &axis)
      : c(reference_position)
      , theta(angle)
      , X_ref(local_reference)
  {
    const double length = axis.norm();
    a = length > 0.0 ? axis / length : Tensor<1, 3>({0.0, 0.0, 1.0});
    const double cs = std::cos(angle), sn = std::sin(angle);
    // Rodrigues: R = cos I + sin [a]x + (1 - cos) a (x) a
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        R[i][j] = (i == j ? cs : 0.0) + (1.0 - cs) * a[i] * a[j];
    R[0][1] -= sn * a[2];
    R[0][2] += sn * a[1];
    R[1][0] += sn * a[2];
    R[1][2] -= sn * a[0];
    R[2][0] -= sn * a[1];
    R[2][1] += sn * a[0];
  }

  Point<3> DiePose<3>::to_global(const Point<3> &X) const
  {
    return c + rotate_vector_to_global(X - X_ref);
  }

  Point<3> DiePose<3>::to_local(const Point<3> &x) const
  {
    return X_ref + rotate_vector_to_local(x - c);
  }

  Tensor<1, 3> DiePose<3>::rotate_vector_to_global(const Tensor<1, 3> &v) const
  {
    return R * v;
  }

  Tensor<1, 3> DiePose<3>::rotate_vector_to_local(const Tensor<1, 3> &v) const
  {
    return v * R; // R^T v
  }

  // ------------------------------------------------------------------ DieMotion

  template <int dim>
  double DieMotion<dim>::difference_step(const double t)
  {
    return 1e-6 * (1.0 + std::abs(t));
  }

  template <int dim>
  Tensor<1, dim> DieMotion<dim>::velocity(const double t, const Point<dim> &X) const
  {
    const double h = difference_step(t);
    return (pose(t + h).to_global(X) - pose(t - h).to_global(X)) / (2.0 * h);
  }

  template <int dim>
  double DieMotion<dim>::angular_velocity(const double t) const
  {
    const double h = difference_step(t);
    return (pose(t + h).angle() - pose(t - h).angle()) / (2.0 * h);
  }

  template <int dim>
  Tensor<1, dim>
  DieMotion<dim>::displacement(const double t0, const double t1, const Point<dim> &X) const
  {
    return pose(t1).to_global(X) - pose(t0).to_global(X);
  }

  // ------------------------------------------------------------------ FixedPose

  template <int dim>
  FixedPose<dim>::FixedPose(const DiePose<dim> &pose)
      : fixed(pose)
  {
  }

  template <int dim>
  DiePose<dim> FixedPose<dim>::pose(const double) const
  {
    return fixed;
  }

  template <int dim>
  Tensor<1, dim> FixedPose<dim>::velocity(const double, const Point<dim> &) const
  {
    return Tensor<1, dim>();
  }

  template <int dim>
  double FixedPose<dim>::angular_velocity(const double) const
  {
    return 0.0;
  }

  // ------------------------------------------------------------------ PrescribedMotion

  template <int dim>
  PrescribedMotion<dim>::PrescribedMotion(VectorTimeFunction<dim> translation,
                                          TimeFunction            rotation,
                                          const Point<dim>       &pivot)
      : PrescribedMotion(std::move(translation), std::move(rotation), pivot, pivot)
  {
  }

  template <int dim>
  PrescribedMotion<dim>::PrescribedMotion(VectorTimeFunction<dim> translation,
                                          TimeFunction            rotation,
                                          const Point<dim>       &pivot,
                                          const Point<dim>       &pivot_rest_position,
                                          const Tensor<1, dim>   &axis)
      : translation(std::move(translation))
      , rotation(std::move(rotation))
      , pivot(pivot)
      , pivot_rest(pivot_rest_position)
      , axis(axis)
  {
  }

  template <int dim>
  PrescribedMotion<dim> PrescribedMotion<dim>::constant_velocity(const Tensor<1, dim> &velocity)
  {
    return PrescribedMotion([velocity](const double t) { return velocity * t; }, TimeFunction());
  }

  template <int dim>
  DiePose<dim> PrescribedMotion<dim>::pose(const double t) const
  {
    const Tensor<1, dim> u = translation ? translation(t) : Tensor<1, dim>();
    return DiePose<dim>(pivot_rest + u, evaluate(rotation, t), pivot, axis);
  }

  // ------------------------------------------------------------------ RollingMotion

  template <int dim>
  RollingMotion<dim>::RollingMotion(const Data &data)
      : d(data)
      , a0(data.initial_center_distance.value_or(data.workpiece_radius + data.die_radius))
  {
    const std::string where = "Rolling motion";
    require(d.workpiece_radius > 0.0, where, "the workpiece pitch radius must be positive");
    require(d.die_radius > 0.0, where, "the die pitch radius must be positive");
    require(a0 > 0.0, where, "the initial centre distance must be positive");
    require(d.direction == 1 || d.direction == -1, where, "the direction must be +1 or -1");
    require(d.beta >= 0.0 && d.beta <= 1.0, where, "the rolling ratio beta must lie in [0, 1]");
    if constexpr (dim == 3)
    {
      const surfaces::Frame3D frame(
          Point<3>(), d.axis.norm() > 0.0 ? d.axis : Tensor<1, 3>({0., 0., 1.}), d.reference);
      d.axis = frame.basis(2);
      e1 = frame.basis(0);
      e2 = frame.basis(1);
    }
  }

  template <int dim>
  double RollingMotion<dim>::line_angle(const double t) const
  {
    return d.initial_line_angle + d.direction * evaluate(d.revolution_angle, t);
  }

  template <int dim>
  double RollingMotion<dim>::center_distance(const double t) const
  {
    return a0 - evaluate(d.feed, t);
  }

  template <int dim>
  Point<dim> RollingMotion<dim>::polar_point(const double r, const double psi) const
  {
    if constexpr (dim == 2)
      return d.workpiece_center + Point<2>(r * std::cos(psi), r * std::sin(psi));
    else
      return d.workpiece_center + r * std::cos(psi) * e1 + r * std::sin(psi) * e2;
  }

  template <int dim>
  Point<dim> RollingMotion<dim>::die_center(const double t) const
  {
    return polar_point(center_distance(t), line_angle(t));
  }

  template <int dim>
  double RollingMotion<dim>::spin_angle(const double t) const
  {
    return d.workpiece_radius / d.die_radius * evaluate(d.revolution_angle, t)
           + (1.0 - d.beta) * evaluate(d.slip_angle, t);
  }

  template <int dim>
  Point<dim> RollingMotion<dim>::pitch_point(const double t) const
  {
    return polar_point(d.workpiece_radius, line_angle(t));
  }

  template <int dim>
  DiePose<dim> RollingMotion<dim>::pose(const double t) const
  {
    const double theta
        = d.initial_die_angle + d.direction * (evaluate(d.revolution_angle, t) + spin_angle(t));
    return DiePose<dim>(die_center(t), theta, Point<dim>(), d.axis);
  }

  template class DieMotion<2>;
  template class DieMotion<3>;
  template class FixedPose<2>;
  template class FixedPose<3>;
  template class PrescribedMotion<2>;
  template class PrescribedMotion<3>;
  template class RollingMotion<2>;
  template class RollingMotion<3>;
} // namespace ausroll::contact
