/**
 * @file rigid_body_modes.h
 * The rigid body modes of a displacement field (translations and rotations), e.g. the near null
 * space of an algebraic multigrid preconditioner.
 */
#pragma once

#include <deal.II/base/point.h>

#include <array>

namespace ausroll::mechanics
{
  /** Number of rigid body modes in @p dim dimensions: dim translations and dim (dim - 1) / 2
      rotations. */
  template <int dim>
  constexpr unsigned int n_rigid_body_modes = dim *(dim + 1) / 2;

  /**
   * The rotations among the rigid body modes, each by the two components {i, j} it couples: the
   * rotation moves component i by x_j and component j by -x_i (2D: the rotation about z; 3D: the
   * rotations about x, y and z, omega x r with omega = -e_x, -e_y, -e_z).
   */
  template <int dim>
  struct RigidRotations;

  template <>
  struct RigidRotations<2>
  {
    static constexpr std::array<std::array<unsigned int, 2>, 1> planes{{{1, 0}}};
  };

  template <>
  struct RigidRotations<3>
  {
    static constexpr std::array<std::array<unsigned int, 2>, 3> planes{{{1, 2}, {2, 0}, {0, 1}}};
  };

  /** Component @p c at the point @p x of rigid body mode @p m: modes 0 ... dim - 1 are the
      translations along the axes, the others the rotations of RigidRotations<dim>, in order. */
  template <int dim>
  double rigid_body_mode(const unsigned int m, const unsigned int c, const dealii::Point<dim> &x)
  {
    if (m < dim)
      return m == c ? 1. : 0.;
    const std::array<unsigned int, 2> &plane = RigidRotations<dim>::planes[m - dim];
    if (c == plane[0])
      return x[plane[1]];
    if (c == plane[1])
      return -x[plane[0]];
    return 0.;
  }
} // namespace ausroll::mechanics
