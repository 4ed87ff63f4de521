/**
 * The direct LinearSolver keeps KLU's symbolic factorisation and pivot order between solves with
 * one sparsity pattern and refactorises only the values. Sequences of matrices on one pattern
 * whose values change the way a Newton iteration changes them (new tangent values, a row that
 * becomes a constraint row, a diagonal entry that falls to near zero so that the kept pivot order
 * is poor) must each be solved as accurately as a fresh pivoting factorisation would: the relative
 * residual |A x - b| / |b| stays at round-off level (bound 1e-12: the matrices are of order 10 and
 * condition numbers below 1e4, so a stable LU leaves 1e-15; the solver's own acceptance bound is
 * 1e-10).
 */
#include <ausroll/mechanics/rigid_body_modes.h>
#include <ausroll/solver/linear_solver.h>

#include <deal.II/base/index_set.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace
{
  using namespace dealii;

  constexpr unsigned int n = 12;

  /** Pattern of a 1D Laplacian with one extra coupling (0, n-1). */
  DynamicSparsityPattern pattern()
  {
    DynamicSparsityPattern dsp(n, n);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = (i > 0 ? i - 1 : 0); j <= std::min(i + 1, n - 1); ++j)
        dsp.add(i, j);
    dsp.add(0, n - 1);
    dsp.add(n - 1, 0);
    return dsp;
  }

  /** A on pattern(), entry (i, j) from @p value (only pattern entries are set). */
  void fill(TrilinosWrappers::SparseMatrix                          &A,
            const std::function<double(unsigned int, unsigned int)> &value)
  {
    A = 0.;
    const DynamicSparsityPattern dsp = pattern();
    for (unsigned int i = 0; i < n; ++i)
      for (auto it = dsp.begin(i); it != dsp.end(i); ++it)
        A.set(i, it->column(), value(i, it->column()));
    A.compress(VectorOperation::insert);
  }

  double relative_residual(const TrilinosWrappers::SparseMatrix &A,
                           const TrilinosWrappers::MPI::Vector  &x,
                           const TrilinosWrappers::MPI::Vector  &b)
  {
    TrilinosWrappers::MPI::Vector r(b);
    A.vmult(r, x);
    r -= b;
    return r.l2_norm() / b.l2_norm();
  }
} // namespace

TEST(LinearSolver, KeptKluPivotsSolveChangedValuesToRoundOff)
{
  const IndexSet                 all = complete_index_set(n);
  TrilinosWrappers::SparseMatrix A;
  A.reinit(all, all, pattern(), MPI_COMM_WORLD);
  TrilinosWrappers::MPI::Vector x(all, MPI_COMM_WORLD), b(all, MPI_COMM_WORLD);
  for (unsigned int i = 0; i < n; ++i)
    b[i] = 1. + 0.1 * i;
  b.compress(VectorOperation::insert);

  ausroll::solver::LinearSolverParameters parameters;
  parameters.type = ausroll::solver::LinearSolverType::direct;
  parameters.direct_package = "KLU";
  ausroll::solver::LinearSolver<2> solver(parameters);

  // 1. a tangent-like matrix: diagonally dominant, unsymmetric coupling (friction, F-bar)
  fill(A, [](unsigned int i, unsigned int j) { return i == j ? 4. : (i < j ? -1. : -1.3); });
  solver.solve(A, x, b);
  EXPECT_LE(relative_residual(A, x, b), 1e-12);

  // 2. new values (softer, plastic): kept pivots are fine
  fill(A, [](unsigned int i, unsigned int j) { return i == j ? 2.5 + 0.1 * i : -0.9; });
  solver.solve(A, x, b);
  EXPECT_LE(relative_residual(A, x, b), 1e-12);

  // 3. row 3 becomes a constraint row (diagonal only, scaled), as a closing contact node does
  fill(A,
       [](unsigned int i, unsigned int j)
       {
         if (i == 3)
           return j == 3 ? 1e3 : 0.;
         return i == j ? 2.5 : -0.9;
       });
  solver.solve(A, x, b);
  EXPECT_LE(relative_residual(A, x, b), 1e-12);

  // 4. the first diagonal entry falls to 1e-9 of the rest while its row and column couple
  //    strongly: the kept (diagonal) pivot order is poor, the solver must pivot again
  fill(A,
       [](unsigned int i, unsigned int j)
       {
         if (i == 0 && j == 0)
           return 1e-9;
         if ((i == 0 && j == 1) || (i == 1 && j == 0))
           return 3.;
         return i == j ? 2. : -0.5;
       });
  solver.solve(A, x, b);
  EXPECT_LE(relative_residual(A, x, b), 1e-12);

  // 5. back to a benign matrix after the pivoting factorisation
  fill(A, [](unsigned int i, unsigned int j) { return i == j ? 4. : -1.; });
  solver.solve(A, x, b);
  EXPECT_LE(relative_residual(A, x, b), 1e-12);
}

// The near null space given to the AMG (mechanics/rigid_body_modes.h): dim (dim + 1) / 2 modes,
// the translations e_k, and rotations that are omega x r: 2D omega = e_z, u = (-y, x); 3D
// omega = -e_k for mode dim + k (the sign is the one the solver has always used). Reference: the
// cross product written out; exact (the modes are copies of coordinates).
TEST(RigidBodyModes, TranslationsAndRotations)
{
  using ausroll::mechanics::n_rigid_body_modes;
  using ausroll::mechanics::rigid_body_mode;
  EXPECT_EQ(n_rigid_body_modes<2>, 3u);
  EXPECT_EQ(n_rigid_body_modes<3>, 6u);
  const dealii::Point<2> p(0.3, -1.7);
  for (unsigned int c = 0; c < 2; ++c)
    for (unsigned int k = 0; k < 2; ++k)
      EXPECT_EQ(rigid_body_mode<2>(k, c, p), c == k ? 1. : 0.);
  EXPECT_EQ(rigid_body_mode<2>(2, 0, p), -p[1]);
  EXPECT_EQ(rigid_body_mode<2>(2, 1, p), p[0]);
  const dealii::Point<3> x(0.3, -1.7, 2.9);
  for (unsigned int k = 0; k < 3; ++k)
  {
    dealii::Tensor<1, 3> omega;
    omega[k] = -1.;
    const dealii::Tensor<1, 3> u = dealii::cross_product_3d(omega, x);
    for (unsigned int c = 0; c < 3; ++c)
    {
      EXPECT_EQ(rigid_body_mode<3>(k, c, x), c == k ? 1. : 0.);
      EXPECT_EQ(rigid_body_mode<3>(3 + k, c, x), u[c]) << "mode " << 3 + k << ", component " << c;
    }
  }
}
