/**
 * @file plane_vectors.h
 * Small helpers for vectors in the plane used by the 2D curves (curve_segment.h, curve_chain.h)
 * and the 2D die shapes built from them.
 */
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <cmath>
#include <limits>
#include <string>

namespace ausroll::geometry::plane
{
  /** +infinity: the open end of a line segment. */
  inline constexpr double inf = std::numeric_limits<double>::infinity();

  /** Unit vector e(a) = (cos a, sin a). */
  inline dealii::Tensor<1, 2> unit(const double a)
  {
    dealii::Tensor<1, 2> e;
    e[0] = std::cos(a);
    e[1] = std::sin(a);
    return e;
  }

  /** Vector @p v rotated by +90 degrees: (-v_y, v_x). */
  inline dealii::Tensor<1, 2> rotate_left(const dealii::Tensor<1, 2> &v)
  {
    dealii::Tensor<1, 2> r;
    r[0] = -v[1];
    r[1] = v[0];
    return r;
  }

  /** Vector @p v rotated by -90 degrees: (v_y, -v_x). */
  inline dealii::Tensor<1, 2> rotate_right(const dealii::Tensor<1, 2> &v)
  {
    dealii::Tensor<1, 2> r;
    r[0] = v[1];
    r[1] = -v[0];
    return r;
  }

  /** z-component of the cross product a x b. */
  inline double cross(const dealii::Tensor<1, 2> &a, const dealii::Tensor<1, 2> &b)
  {
    return a[0] * b[1] - a[1] * b[0];
  }

  /** @p a wrapped into [0, @p period). */
  inline double positive_modulo(const double a, const double period)
  {
    double r = std::fmod(a, period);
    if (r < 0.0)
      r += period;
    return (r >= period) ? 0.0 : r;
  }

  /** Rotate @p p about the origin by @p angle (counter-clockwise). */
  inline dealii::Point<2> rotate(const dealii::Point<2> &p, const double angle)
  {
    const double c = std::cos(angle), s = std::sin(angle);
    return dealii::Point<2>(c * p[0] - s * p[1], s * p[0] + c * p[1]);
  }

  /** Polar angle of @p v. */
  inline double polar_angle(const dealii::Tensor<1, 2> &v)
  {
    return std::atan2(v[1], v[0]);
  }

  /** The entry named in the messages of the 2D curves and the die shapes built from them. */
  inline const std::string curve_entry = "Die surface";
} // namespace ausroll::geometry::plane
