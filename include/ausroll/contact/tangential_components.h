/**
 * @file tangential_components.h
 * The tangential components of a contact node's force, slip or slip direction (dim - 1 numbers
 * in the die's tangent basis): their magnitude.
 */
#pragma once

#include <array>
#include <cmath>
#include <cstddef>

namespace ausroll::contact
{
  /** Magnitude of tangential components (2D: |R_t| as before; 3D: the Euclidean norm). */
  template <std::size_t n>
  double magnitude(const std::array<double, n> &v)
  {
    if constexpr (n == 1)
      return std::abs(v[0]);
    else
    {
      double sum = 0.;
      for (const double x : v)
        sum += x * x;
      return std::sqrt(sum);
    }
  }
} // namespace ausroll::contact
