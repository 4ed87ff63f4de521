/**
 * @file out_of_plane_solve.h
 * The Newton increment of generalized plane strain: the bordered system of the displacement and
 * the out-of-plane stretch, solved by the Schur complement on the scalar.
 */
#pragma once

#include <ausroll/mechanics/mechanical_system.h>
#include <ausroll/solver/linear_solver.h>

namespace ausroll::solver
{
  /**
   * The increment (du, dlambda) of the bordered Newton system of generalized plane strain
   * (mechanics::GeneralizedPlaneStrain) at the last assembly of @p system:
   *
   *   K du + k_ue dlambda = -r,   k_eu . du + k_ee dlambda = -r_lambda.
   *
   * With the one factorisation of K (LinearSolver::solve with two right-hand sides):
   * K x_r = -r (the assembled rhs, inhomogeneous constraints), K x_e = k_ue (condensed like the
   * residual; homogeneous constraints); du = x_r - dlambda x_e with the distributed vectors, so
   * that k_eu . du sees the prescribed and hanging-node parts of the increment, and
   *
   *   dlambda = (-r_lambda - k_eu . x_r) / (k_ee - k_eu . x_e)
   *
   * (the Schur complement of K, a scalar; the dot products are sums over the ranks). Sets
   * system.increment (distributed) and out_of_plane.increment; the caller has set newton_start.
   * Throws RunFailure when the Schur complement vanishes (no axial stiffness left).
   */
  template <int dim>
  LinearSolveInfo solve_out_of_plane_increment(const LinearSolver<dim>          &linear_solver,
                                               mechanics::MechanicalSystem<dim> &system);
} // namespace ausroll::solver
