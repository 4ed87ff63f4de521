/**
 * The direct LinearSolver keeps KLU's symbolic factorisation and pivot order between solves with
 * one sparsity pattern and refactorises only the values. Sequences of matrices on one pattern
 * whose values change the way a Newton iteration changes them (new tangent values, a row that
 * becomes a constraint row, a diagonal entry that falls to near zero so that the kept pivot order
 * is poor) must each be solved as accurately as a fresh pivoting factorisation would: the relative
 * residual |A x - b| / |b| stays at round-off level (bound 1e-12: the matrices are of order 10 and
 * condition numbers below 1e4, so a stable LU leaves 1e-15; the solver's own acceptance bound is
 * 1e-10).
 *
 * The iterative path: the forcing term of inexact Newton (ForcingTerm, `Krylov tolerance =
 * adaptive`) against the Eisenstat-Walker formulas evaluated by hand, the rule that keeps or
 * rebuilds the AMG (AmgReuse, `AMG reuse`), and the kept AMG at work in LinearSolver on a 3D
 * Laplacian.
 */
#include <ausroll/mechanics/rigid_body_modes.h>
#include <ausroll/solver/amg_reuse.h>
#include <ausroll/solver/forcing_term.h>
#include <ausroll/solver/linear_solver.h>

#include <deal.II/base/index_set.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <gtest/gtest.h>

#include <array>
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

namespace
{
  using ausroll::solver::AmgReuse;
  using ausroll::solver::ForcingTerm;
  using ausroll::solver::KrylovTolerance;
  using ausroll::solver::LinearSolverParameters;

  LinearSolverParameters forcing_parameters(const KrylovTolerance rule, const double eta_max)
  {
    LinearSolverParameters p;
    p.krylov_tolerance = rule;
    p.relative_tolerance = 1e-10;
    p.maximum_forcing_term = eta_max;
    return p;
  }
} // namespace

// Krylov tolerance = fixed: every solve to Relative tolerance, whatever the residuals.
TEST(ForcingTerm, FixedIsTheRelativeTolerance)
{
  ForcingTerm eta(forcing_parameters(KrylovTolerance::fixed, 1e-2));
  EXPECT_EQ(eta.next(1., 1e-6), 1e-10);
  EXPECT_EQ(eta.next(1e-3, 1e-6), 1e-10);
  eta.restart();
  EXPECT_EQ(eta.next(5e-6, 1e-6), 1e-10);
}

// Eisenstat-Walker choice 2 (gamma 0.9, alpha 2) with Kelley's safeguards, each branch against the
// formula evaluated by hand (relative bound 1e-14: a few operations in double precision).
TEST(ForcingTerm, EisenstatWalkerChoiceTwoWithSafeguards)
{
  const double tol = 1e-8; // Newton tolerance of the iterates (same unit as the residuals)
  ForcingTerm  eta(forcing_parameters(KrylovTolerance::adaptive, 1e-2));
  // first solve: eta_max
  EXPECT_EQ(eta.next(1., tol), 1e-2);
  // |r| falls by 10: 0.9 * 0.1^2 = 9e-3 (safeguard 0.9 * 1e-4 < 0.1 inactive, end game 5e-8)
  EXPECT_NEAR(eta.next(0.1, tol), 9e-3, 1e-14 * 9e-3);
  // |r| falls by 1e3: 0.9 * 1e-6 = 9e-7 (end game 0.5 * 1e-8 / 1e-4 = 5e-5 is larger: 5e-5)
  EXPECT_NEAR(eta.next(1e-4, tol), 5e-5, 1e-14 * 5e-5);
  // near the tolerance the end game bound wins and eta_max caps it: 0.5 * 1e-8 / 2e-8 = 0.25
  EXPECT_EQ(eta.next(2e-8, tol), 1e-2);
  // slow convergence: |r| falls by 2 only: 0.9 * 0.25 = 0.225, capped at eta_max
  eta.restart();
  EXPECT_EQ(eta.next(1., 1e-12), 1e-2);
  EXPECT_EQ(eta.next(0.5, 1e-12), 1e-2);
  // a fast fall with a tiny Newton tolerance: the floor is Relative tolerance (0.9 * 1e-16)
  EXPECT_EQ(eta.next(0.5e-8, 1e-30), 1e-10);
}

TEST(ForcingTerm, SafeguardKeepsEtaFromFallingFasterThanItsSquare)
{
  // eta_max 0.5: after eta = 0.5 the safeguard 0.9 * 0.25 = 0.225 > 0.1 bounds the next eta
  // from below although |r| fell by 1e4 (0.9 * 1e-8); with eta = 0.225 next, 0.9 * 0.225^2 =
  // 0.0455625 < 0.1: no safeguard, the plain formula 0.9 * 1e-2 = 9e-3 holds
  ForcingTerm eta(forcing_parameters(KrylovTolerance::adaptive, 0.5));
  EXPECT_EQ(eta.next(1., 1e-12), 0.5);
  EXPECT_NEAR(eta.next(1e-4, 1e-12), 0.225, 1e-14);
  EXPECT_NEAR(eta.next(1e-5, 1e-12), 9e-3, 1e-14 * 9e-3);
}

TEST(ForcingTerm, RestartAndZeroResidualGiveTheMaximum)
{
  ForcingTerm eta(forcing_parameters(KrylovTolerance::adaptive, 1e-3));
  // the first iterate of a step that only has to meet constraints has |r| = 0
  EXPECT_EQ(eta.next(0., 1e-6), 1e-3);
  EXPECT_EQ(eta.next(10., 1e-6), 1e-3); // no ratio to a zero residual
  EXPECT_EQ(eta.next(1., 1e-6), 1e-3);  // 0.9 * 0.1^2 = 9e-3 capped at eta_max
  EXPECT_NEAR(eta.next(1e-2, 1e-6), 9e-5, 1e-14 * 9e-5);
  // a status pass: new constraints, the residual jumps up; the history starts again
  eta.restart();
  EXPECT_EQ(eta.next(100., 1e-6), 1e-3);
}

// The rate of a solve is its Krylov iterations per decade of residual reduction.
TEST(AmgReuse, IterationsPerDecade)
{
  EXPECT_NEAR(AmgReuse::iterations_per_decade(60, 1e-10), 6., 1e-13);
  EXPECT_NEAR(AmgReuse::iterations_per_decade(15, 1e-2), 7.5, 1e-13);
  EXPECT_EQ(AmgReuse::iterations_per_decade(0, 1e-10), 0.);
  EXPECT_EQ(AmgReuse::iterations_per_decade(5, 0.), 0.);
  EXPECT_EQ(AmgReuse::iterations_per_decade(5, 1.), 0.);
}

TEST(AmgReuse, WithoutReuseEverySolveSetsUp)
{
  AmgReuse rule(false, 1.5);
  EXPECT_TRUE(rule.needs_setup());
  rule.set_up();
  rule.solved(60, 1e-10);
  EXPECT_TRUE(rule.needs_setup());
}

TEST(AmgReuse, KeptUntilTheRateGrowsPastTheFactor)
{
  AmgReuse rule(true, 1.5);
  EXPECT_TRUE(rule.needs_setup()); // nothing built yet
  rule.set_up();
  EXPECT_FALSE(rule.needs_setup());
  rule.solved(0, 1.); // b = 0: says nothing, no reference
  EXPECT_EQ(rule.reference_rate(), 0.);
  rule.solved(4, 1e-2); // too short to judge: no reference
  EXPECT_EQ(rule.reference_rate(), 0.);
  rule.solved(60, 1e-10); // reference: 6 per decade
  EXPECT_NEAR(rule.reference_rate(), 6., 1e-13);
  rule.solved(17, 1e-2); // 8.5 per decade <= 1.5 * 6 = 9: kept (a looser solve compares)
  EXPECT_FALSE(rule.needs_setup());
  rule.solved(9, 1e-1); // 9 per decade but too short to judge: kept
  EXPECT_FALSE(rule.needs_setup());
  rule.solved(89, 1e-9); // 9.89 per decade > 9: rebuild
  EXPECT_TRUE(rule.needs_setup());
  rule.set_up(); // the new set-up takes its own reference
  EXPECT_EQ(rule.reference_rate(), 0.);
  rule.solved(100, 1e-10);
  EXPECT_NEAR(rule.reference_rate(), 10., 1e-13);
  EXPECT_FALSE(rule.needs_setup());
  rule.invalidate(); // mesh change or failed solve
  EXPECT_TRUE(rule.needs_setup());
}

namespace
{
  /**
   * 7-point diffusion matrix of an m^3 grid with Dirichlet boundary and a coefficient that jumps
   * over four decades between neighbouring links (so that the AMG needs tens of iterations, as
   * for the contact tangents), plus @p shift on the diagonal.
   */
  void laplacian_3d(TrilinosWrappers::SparseMatrix &A, const unsigned int m, const double shift)
  {
    const unsigned int     N = m * m * m;
    const auto             index = [m](int i, int j, int k) { return (k * m + j) * m + i; };
    DynamicSparsityPattern dsp(N, N);
    for (int k = 0; k < int(m); ++k)
      for (int j = 0; j < int(m); ++j)
        for (int i = 0; i < int(m); ++i)
        {
          dsp.add(index(i, j, k), index(i, j, k));
          for (const auto &d : {std::array<int, 3>{{1, 0, 0}},
                                std::array<int, 3>{{0, 1, 0}},
                                std::array<int, 3>{{0, 0, 1}}})
            for (const int sign : {-1, 1})
            {
              const int a = i + sign * d[0], b = j + sign * d[1], c = k + sign * d[2];
              if (a >= 0 && a < int(m) && b >= 0 && b < int(m) && c >= 0 && c < int(m))
                dsp.add(index(i, j, k), index(a, b, c));
            }
        }
    if (A.m() != N)
    {
      const IndexSet all = complete_index_set(N);
      A.reinit(all, all, dsp, MPI_COMM_WORLD);
    }
    // the link coefficient of rows p and q (symmetric)
    const auto link = [](const unsigned int p, const unsigned int q)
    { return std::pow(10., 2. * std::sin(0.9 * (p + q) + 0.37 * p * q)); };
    A = 0.;
    for (unsigned int r = 0; r < N; ++r)
    {
      // six links of coefficient 1 (those to the Dirichlet boundary stay so), the inner ones
      // replaced by their coefficients below
      double diagonal = shift + 6.;
      for (auto it = dsp.begin(r); it != dsp.end(r); ++it)
        if (it->column() != r)
        {
          A.set(r, it->column(), -link(r, it->column()));
          diagonal += link(r, it->column()) - 1.;
        }
      A.set(r, r, diagonal);
    }
    A.compress(VectorOperation::insert);
  }
} // namespace

// A kept AMG in LinearSolver on a sequence of matrices with one pattern (as Newton iterations
// give): one set-up is used while it serves; a solve that needs more than `AMG rebuild factor`
// (1.5) times the iterations per decade of the first solve with it is still converged, and the
// next solve sets up anew; matrix_pattern_changed() forces a set-up. Every solve meets its
// tolerance (true relative residual; bound: the tolerance with 1 % for round-off, as
// right-preconditioned GMRES stops on the true residual). Without reuse every solve sets up.
TEST(LinearSolver, KeptAmgServesUntilItsRateGrows)
{
  constexpr unsigned int         m = 16; // 4096 unknowns: ML builds levels (its coarse limit 2000)
  TrilinosWrappers::SparseMatrix A;
  laplacian_3d(A, m, 0.);
  const IndexSet                all = complete_index_set(m * m * m);
  TrilinosWrappers::MPI::Vector x(all, MPI_COMM_WORLD), b(all, MPI_COMM_WORLD);
  for (unsigned int i = 0; i < b.size(); ++i)
    b[i] = 1. + std::sin(0.37 * i);
  b.compress(VectorOperation::insert);

  for (const bool reuse : {true, false})
  {
    SCOPED_TRACE(reuse ? "AMG reuse = true" : "AMG reuse = false");
    LinearSolverParameters parameters;
    parameters.type = ausroll::solver::LinearSolverType::iterative;
    parameters.amg_reuse = reuse;
    ausroll::solver::LinearSolver<3> solver(parameters);
    // 1. a new set-up, solved to Relative tolerance 1e-10
    laplacian_3d(A, m, 0.);
    const auto   first = solver.solve(A, x, b);
    const double first_reduction = relative_residual(A, x, b);
    EXPECT_TRUE(first.amg_setup);
    EXPECT_LE(first_reduction, 1.01e-10);
    // 2. the same matrix to 1e-2 (a loose forcing term): kept, fewer iterations
    const auto loose = solver.solve(A, x, b, 1e-2);
    EXPECT_EQ(loose.relative_tolerance, 1e-2);
    EXPECT_EQ(loose.amg_setup, !reuse);
    EXPECT_LE(relative_residual(A, x, b), 1.01e-2);
    EXPECT_LT(loose.iterations, first.iterations);
    // 3. new values: a diagonal shift that dominates where the links are weak (0.01); the kept
    //    set-up still converges, but slower than the rebuild factor allows
    laplacian_3d(A, m, 0.5);
    const auto   shifted = solver.solve(A, x, b);
    const double shifted_reduction = relative_residual(A, x, b);
    EXPECT_EQ(shifted.amg_setup, !reuse);
    EXPECT_LE(shifted_reduction, 1.01e-10);
    // 4. the same matrix again: a new set-up after the slow solve (with reuse: because of it),
    //    which needs fewer iterations than the kept one did
    const auto again = solver.solve(A, x, b);
    EXPECT_TRUE(again.amg_setup);
    EXPECT_LE(relative_residual(A, x, b), 1.01e-10);
    if (reuse)
    {
      EXPECT_GT(AmgReuse::iterations_per_decade(shifted.iterations, shifted_reduction),
                1.5 * AmgReuse::iterations_per_decade(first.iterations, first_reduction));
      EXPECT_LT(again.iterations, shifted.iterations);
    }
    EXPECT_EQ(solver.n_amg_setups(), reuse ? 2u : 4u);
    // 5. a new pattern (mesh change): a new set-up
    solver.matrix_pattern_changed();
    const auto after_change = solver.solve(A, x, b);
    EXPECT_TRUE(after_change.amg_setup);
    EXPECT_EQ(solver.n_amg_setups(), reuse ? 3u : 5u);
  }
}
