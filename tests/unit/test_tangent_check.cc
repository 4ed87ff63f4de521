/**
 * The finite-difference check of a Newton tangent along the Newton increment
 * (solver::linear_model_errors(), the core of `AUSROLL_TANGENT_CHECK`), on the residual
 * r(u) = A u + c u^3 (componentwise cube) of three unknowns, whose exact Jacobian is
 * J = A + 3 c diag(u^2). With the exact Jacobian the error of the linear model must fall like eps
 * (it is eps |r''(d, d)| / (2 |r|) to leading order); with the cubic term left out of the
 * tangent it must stay at the analytic plateau |3 c diag(u^2) d| / |r(u)|.
 */
#include <ausroll/solver/tangent_check.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <gtest/gtest.h>

#include <cmath>

namespace
{
  using dealii::FullMatrix;
  using TestVector = dealii::Vector<double>;

  const double c = 2.;

  FullMatrix<double> matrix_a()
  {
    FullMatrix<double> a(3, 3);
    const double       entries[3][3] = {{4., 1., 0.}, {1., 3., 0.5}, {0., 0.5, 2.}};
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        a(i, j) = entries[i][j];
    return a;
  }

  TestVector residual(const TestVector &u)
  {
    TestVector r(3);
    matrix_a().vmult(r, u);
    for (unsigned int i = 0; i < 3; ++i)
      r[i] += c * u[i] * u[i] * u[i];
    return r;
  }

  /** Newton increment d = -K^-1 r(u) with K = A (+ 3 c diag(u^2) if @p exact). */
  TestVector increment(const TestVector &u, const bool exact)
  {
    FullMatrix<double> k = matrix_a();
    if (exact)
      for (unsigned int i = 0; i < 3; ++i)
        k(i, i) += 3. * c * u[i] * u[i];
    k.gauss_jordan();
    TestVector d(3);
    k.vmult(d, residual(u));
    d *= -1.;
    return d;
  }

  std::vector<double> errors_along(const TestVector &u, const TestVector &d)
  {
    const std::function<TestVector(double)> residual_at = [&](const double eps)
    {
      TestVector v = u;
      v.add(eps, d);
      return residual(v);
    };
    return ausroll::solver::linear_model_errors(residual_at, residual(u), {1e-2, 1e-3, 1e-4});
  }

  TestVector iterate()
  {
    TestVector u(3);
    u[0] = 0.7;
    u[1] = -0.4;
    u[2] = 1.1;
    return u;
  }
} // namespace

TEST(TangentCheck, ConsistentTangentGivesAnErrorFallingLikeEps)
{
  const TestVector          u = iterate();
  const std::vector<double> e = errors_along(u, increment(u, true));
  // leading order eps |r''(d, d)| / (2 |r|), r''(d, d)_i = 6 c u_i d_i^2: a factor 10 per decade
  // of eps to 1e-6 relative (round-off of the differences is ~1e-16 / 1e-4, far below)
  const TestVector d = increment(u, true);
  TestVector       second(3);
  for (unsigned int i = 0; i < 3; ++i)
    second[i] = 6. * c * u[i] * d[i] * d[i];
  const double expected_slope = second.l2_norm() / (2. * residual(u).l2_norm());
  for (unsigned int k = 0; k < e.size(); ++k)
  {
    const double eps = std::pow(10., -2. - k);
    EXPECT_NEAR(e[k], expected_slope * eps, 0.05 * expected_slope * eps) << "eps = " << eps;
  }
}

TEST(TangentCheck, InconsistentTangentLeavesThePlateauOfTheMissingTerm)
{
  const TestVector u = iterate();
  const TestVector d = increment(u, false); // the tangent without the cubic term
  TestVector       missing(3);
  for (unsigned int i = 0; i < 3; ++i)
    missing[i] = 3. * c * u[i] * u[i] * d[i];
  const double              plateau = missing.l2_norm() / residual(u).l2_norm();
  const std::vector<double> e = errors_along(u, d);
  ASSERT_GT(plateau, 0.1); // a substantial error, not round-off
  // at eps = 1e-4 the second-order part is below 1e-3 of the plateau
  EXPECT_NEAR(e[2], plateau, 1e-3 * plateau);
  EXPECT_NEAR(e[1], plateau, 1e-2 * plateau);
}
