// Unit tests of the isotropic tensor functions of the finite-strain models (tensor_functions.h):
// the closed-form spectral decomposition against deal.II's QL eigensolver and against tensors
// built from known eigenpairs (random, plane, equal and nearly equal eigenvalues, extreme
// scales), the logarithm and the exponential and their derivatives against central finite
// differences, the polar decomposition.
//
// Tolerances: the decomposition is backward stable, so V diag(x) V^T reproduces X to a few
// machine epsilons of |X|, and by Weyl's inequality each eigenvalue is within a few eps |X| of the
// exact one (bound 1e-14 |X|, about 50 eps, for the 3x3 products and sums involved); an
// eigenvector is determined only up to an angle eps |X| / gap (Davis-Kahan), so it is compared
// with deal.II's only for a gap above 1e-3 |X|: then 1 - |n . n_ref| = angle^2 / 2 is below the
// rounding of the dot product (bound 1e-14). Finite differences: central, h = 1e-6, truncation
// about h^2 |f'''| ~ 1e-12 and round-off eps / h ~ 1e-10 relative (bound 1e-8).
#include <ausroll/core/exceptions.h>
#include <ausroll/material/tensor_functions.h>

#include "material_test_utilities.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

using namespace ausroll::material;
using dealii::SymmetricTensor;
using dealii::Tensor;

namespace
{
  std::mt19937                           rng(7);
  std::uniform_real_distribution<double> uniform(-1., 1.);

  /** A random rotation: an orthonormal right-handed frame from two random vectors. */
  Tensor<2, 3> random_rotation()
  {
    Tensor<1, 3> a, b;
    for (unsigned int i = 0; i < 3; ++i)
    {
      a[i] = uniform(rng);
      b[i] = uniform(rng);
    }
    a /= a.norm();
    b -= (a * b) * a;
    b /= b.norm();
    const Tensor<1, 3> c = dealii::cross_product_3d(a, b);
    Tensor<2, 3>       Q;
    for (unsigned int i = 0; i < 3; ++i)
    {
      Q[i][0] = a[i];
      Q[i][1] = b[i];
      Q[i][2] = c[i];
    }
    return Q;
  }

  /** Q diag(x) Q^T. */
  SymmetricTensor<2, 3> from_eigenpairs(const Tensor<2, 3> &Q, const std::array<double, 3> &x)
  {
    SymmetricTensor<2, 3> D;
    for (unsigned int a = 0; a < 3; ++a)
      D[a][a] = x[a];
    return rotate(Q, D);
  }

  /** max |X - sum_a x_a n_a (x) n_a| / |X|, the backward error of the decomposition. */
  double reconstruction_error(const SymmetricTensor<2, 3> &X, const SpectralDecomposition &s)
  {
    return (spectral_sum(s, s.values) - X).norm() / X.norm();
  }

  /** max |n_a . n_b - delta_ab|. */
  double orthonormality_error(const SpectralDecomposition &s)
  {
    double e = 0.;
    for (unsigned int a = 0; a < 3; ++a)
      for (unsigned int b = 0; b < 3; ++b)
        e = std::max(e, std::abs(s.vectors[a] * s.vectors[b] - (a == b ? 1. : 0.)));
    return e;
  }

  /**
   * The largest errors of decompositions s of tensors X against their reference eigenvalues:
   * eigenvalues and reconstruction relative to |X|, orthonormality of the eigenvectors.
   */
  struct DecompositionErrors
  {
    double values = 0., reconstruction = 0., orthonormality = 0.;

    void add(const SymmetricTensor<2, 3> &X,
             const SpectralDecomposition &s,
             const std::array<double, 3> &reference_values)
    {
      for (unsigned int a = 0; a < 3; ++a)
        values = std::max(values, std::abs(s.values[a] - reference_values[a]) / X.norm());
      reconstruction = std::max(reconstruction, reconstruction_error(X, s));
      orthonormality = std::max(orthonormality, orthonormality_error(s));
    }

    /** Prints them and expects round-off (1e-14, about 50 eps). */
    void expect_round_off(const char *what) const
    {
      std::printf("[ spectral decomposition ] %s: eigenvalues %.1e |X|, reconstruction %.1e, "
                  "orthonormality %.1e\n",
                  what,
                  values,
                  reconstruction,
                  orthonormality);
      EXPECT_LT(values, 1e-14) << what;
      EXPECT_LT(reconstruction, 1e-14) << what;
      EXPECT_LT(orthonormality, 1e-14) << what;
    }
  };

  SymmetricTensor<2, 3> logarithm_value(const SymmetricTensor<2, 3> &X)
  {
    return logarithm(X);
  }

  SymmetricTensor<2, 3> exponential_value(const SymmetricTensor<2, 3> &X)
  {
    return exponential(X);
  }

  /**
   * max over the directions dX = e_k (x) e_l (k <= l) of |fd - D : dX| / |D : dX|, fd the central
   * difference of @p f at @p X (h = 1e-6; the bound 1e-8 of the file comment).
   */
  double derivative_error(SymmetricTensor<2, 3> (*f)(const SymmetricTensor<2, 3> &),
                          const SymmetricTensor<2, 3> &X,
                          const SymmetricTensor<4, 3> &D)
  {
    const double h = 1e-6;
    double       error = 0.;
    for (unsigned int k = 0; k < 3; ++k)
      for (unsigned int l = k; l < 3; ++l)
      {
        SymmetricTensor<2, 3> dX;
        dX[k][l] = 1.;
        const SymmetricTensor<2, 3> fd = (f(X + h * dX) - f(X - h * dX)) / (2. * h);
        error = std::max(error, (fd - D * dX).norm() / (D * dX).norm());
      }
    return error;
  }

  /**
   * Random symmetric tensors: general ones, plane ones (x_3 principal, as in a plane-strain
   * model), elastic left Cauchy-Green tensors I + 2 eps with |eps| ~ 1e-3, and general ones
   * scaled by 1e-150 and 1e150.
   */
  std::vector<SymmetricTensor<2, 3>> random_tensors()
  {
    std::vector<SymmetricTensor<2, 3>> samples;
    for (int s = 0; s < 400; ++s)
    {
      SymmetricTensor<2, 3> X;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = i; j < 3; ++j)
          X[i][j] = uniform(rng);
      switch (s % 5)
      {
        case 1: // plane
          X[0][2] = X[1][2] = 0.;
          break;
        case 2: // b_e close to the identity
          X = dealii::unit_symmetric_tensor<3>() + 2e-3 * X;
          break;
        case 3:
          X *= 1e-150;
          break;
        case 4:
          X *= 1e150;
          break;
        default:
          break;
      }
      samples.push_back(X);
    }
    return samples;
  }
} // namespace

TEST(TensorFunctions, SpectralDecompositionMatchesDealIIOnRandomTensors)
{
  DecompositionErrors errors;
  double              max_vectors = 0.;
  int                 n_vectors_compared = 0;
  for (const auto &X : random_tensors())
  {
    const SpectralDecomposition s = spectral_decomposition(X);
    // deal.II's QL fails on the tensors of norm 1e150 or 1e-150 (it over- or underflows): its
    // reference is taken for X / |X| and scaled back (a rounding of eps relative)
    const double scale = X.norm();
    const auto   reference = dealii::eigenvectors(
        X / scale, dealii::SymmetricTensorEigenvectorMethod::ql_implicit_shifts);
    std::array<double, 3> reference_values;
    for (unsigned int a = 0; a < 3; ++a)
    {
      reference_values[a] = scale * reference[a].first;
      EXPECT_EQ(s.values[a], s.shifted_values[a] + s.shift);
      // the eigenvector, where its eigenvalue is separated from the others (up to its sign)
      double gap = std::numeric_limits<double>::max();
      for (unsigned int b = 0; b < 3; ++b)
        if (b != a)
          gap = std::min(gap, std::abs(reference[a].first - reference[b].first));
      if (gap > 1e-3)
      {
        max_vectors = std::max(max_vectors, 1. - std::abs(s.vectors[a] * reference[a].second));
        ++n_vectors_compared;
      }
    }
    EXPECT_GE(s.values[0], s.values[1]);
    EXPECT_GE(s.values[1], s.values[2]);
    errors.add(X, s, reference_values);
  }
  errors.expect_round_off("vs deal.II");
  std::printf("[ spectral decomposition ] eigenvectors vs deal.II: 1 - |n . n_ref| %.1e (%d "
              "compared)\n",
              max_vectors,
              n_vectors_compared);
  EXPECT_LT(max_vectors, 1e-14);
  EXPECT_GT(n_vectors_compared, 1000);
}

TEST(TensorFunctions, SpectralDecompositionOfEqualAndNearlyEqualEigenvalues)
{
  // X = Q diag(x) Q^T with two eigenvalues split by 0 ... 1e-4 (the pair above and below the
  // third one, so that the distinct eigenvalue is the largest and the smallest), in random frames
  // and in the coordinate frame (the plane path).
  DecompositionErrors errors;
  double              max_third = 0.;
  for (const double split : {0., 3e-16, 1e-15, 1e-12, 1e-8, 1e-4})
    for (const double third : {0.7, 1.9})
      for (int frame = 0; frame < 20; ++frame)
      {
        const Tensor<2, 3> Q
            = frame == 0 ? Tensor<2, 3>(dealii::unit_symmetric_tensor<3>()) : random_rotation();
        const std::array<double, 3> x = {{1.4, 1.4 + split, third}};
        const SymmetricTensor<2, 3> X = from_eigenpairs(Q, x);
        const SpectralDecomposition s = spectral_decomposition(X);
        std::array<double, 3>       sorted = x;
        std::sort(sorted.begin(), sorted.end(), std::greater<double>());
        errors.add(X, s, sorted);
        // the distinct eigenvector is the third column of Q
        const unsigned int distinct = third > 1.4 ? 0 : 2;
        Tensor<1, 3>       q;
        for (unsigned int i = 0; i < 3; ++i)
          q[i] = Q[i][2];
        max_third = std::max(max_third, 1. - std::abs(s.vectors[distinct] * q));
      }
  errors.expect_round_off("two (nearly) equal eigenvalues");
  std::printf("[ spectral decomposition ] distinct eigenvector: 1 - |n . q| %.1e\n", max_third);
  EXPECT_LT(max_third, 1e-14); // separated by 0.7 |X| / 3 or more: a well-conditioned vector

  // three equal eigenvalues, exactly and up to a small perturbation p of two entries (exact
  // eigenvalues 2.5 + sqrt(1.25) p, 2.5, 2.5 - sqrt(1.25) p)
  DecompositionErrors triple;
  for (const double perturbation : {0., 1e-16, 1e-13})
  {
    SymmetricTensor<2, 3> X = 2.5 * dealii::unit_symmetric_tensor<3>();
    X[0][1] += perturbation;
    X[1][2] -= 0.5 * perturbation;
    const double d = std::sqrt(1.25) * perturbation;
    triple.add(X, spectral_decomposition(X), {{2.5 + d, 2.5, 2.5 - d}});
  }
  triple.expect_round_off("three (nearly) equal eigenvalues");
}

TEST(TensorFunctions, EigenvalueDifferencesNearTheIdentityAreAccurate)
{
  // b_e = I + 2 eps with eigenvalues 1 + d_a, d_a ~ 1e-3 .. 1e-9: the divided differences of the
  // derivatives need x_a - x_b to a few eps absolute (not relative to d), which the shifted
  // eigenvalues give. Reference: the intended eigenvalues (the rounding of X = Q diag(x) Q^T
  // perturbs them by a few eps).
  double max_error = 0.;
  for (const double d : {1e-3, 1e-6, 1e-9})
    for (int frame = 0; frame < 20; ++frame)
    {
      const std::array<double, 3> x = {{1. + d, 1. - 0.3 * d, 1. - 0.7 * d}};
      const SymmetricTensor<2, 3> X = from_eigenpairs(random_rotation(), x);
      const SpectralDecomposition s = spectral_decomposition(X);
      // differences x_0 - x_1 and x_1 - x_2 against 1.3 d and 0.4 d
      max_error
          = std::max(max_error, std::abs(s.shifted_values[0] - s.shifted_values[1] - 1.3 * d));
      max_error
          = std::max(max_error, std::abs(s.shifted_values[1] - s.shifted_values[2] - 0.4 * d));
    }
  std::printf("[ spectral decomposition ] eigenvalue differences near I: %.1e absolute\n",
              max_error);
  // the rounding of X = Q diag(x) Q^T itself is a few eps (entries ~ 1)
  EXPECT_LT(max_error, 2e-15);
}

TEST(TensorFunctions, DiagonalInEigenbasisDetectsCoaxialTensors)
{
  // Y = ln X shares the eigenvectors of X: its diagonal in them is ln x_a (to round-off of the
  // entries of Y, |Y| ~ 1: bound 1e-15); a tensor with another principal frame is rejected.
  for (int sample = 0; sample < 20; ++sample)
  {
    const Tensor<2, 3>          Q = random_rotation();
    const std::array<double, 3> x = {{1.3 + 0.2 * uniform(rng), 1.0, 0.6}};
    const SymmetricTensor<2, 3> X = from_eigenpairs(Q, x);
    const SpectralDecomposition s = spectral_decomposition(X);
    std::array<double, 3>       y;
    ASSERT_TRUE(diagonal_in_eigenbasis(s, logarithm(X), 1e-15, y));
    for (unsigned int a = 0; a < 3; ++a)
      EXPECT_NEAR(y[a], std::log(s.values[a]), 1e-15);
    SymmetricTensor<2, 3> Y = logarithm(X);
    Y[0][1] += 1e-6;
    EXPECT_FALSE(diagonal_in_eigenbasis(s, Y, 1e-15, y));
    EXPECT_TRUE(diagonal_in_eigenbasis(s, Y, 1e-5, y)); // the tolerance is the caller's
  }
}

TEST(TensorFunctions, SpectralDecompositionOfANaNIsNaNAndTheLogarithmFails)
{
  SymmetricTensor<2, 3> X = dealii::unit_symmetric_tensor<3>();
  X[0][1] = std::numeric_limits<double>::quiet_NaN();
  const SpectralDecomposition s = spectral_decomposition(X);
  for (unsigned int a = 0; a < 3; ++a)
    EXPECT_TRUE(std::isnan(s.values[a])) << a;
  EXPECT_THROW(logarithm(X), ausroll::RunFailure);
  SymmetricTensor<2, 3> singular = dealii::unit_symmetric_tensor<3>();
  singular[2][2] = 0.;
  EXPECT_THROW(logarithm(singular), ausroll::RunFailure);
}

TEST(TensorFunctions, LogarithmAndExponentialDerivativesMatchFiniteDifferences)
{
  // Random SPD tensors (general and plane), tensors with exactly and nearly repeated eigenvalues
  // and the identity.
  std::vector<SymmetricTensor<2, 3>> samples;
  samples.push_back(dealii::unit_symmetric_tensor<3>());
  for (const double split : {0., 1e-12, 1e-8, 1e-5, 0.3})
  {
    const Tensor<2, 3> Q = random_rotation();
    samples.push_back(from_eigenpairs(Q, {{1.4, 1.4 + split, 0.7}}));
    samples.push_back(from_eigenpairs(Q, {{1.4, 1.4 + split, 1.9}}));
  }
  for (int s = 0; s < 20; ++s)
  {
    Tensor<2, 3> G;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        G[i][j] = (i == j ? 1. : 0.)
                  + (s % 2 == 1 && i != j && (i == 2 || j == 2) ? 0. : 0.4 * uniform(rng));
    samples.push_back(dealii::symmetrize(G * dealii::transpose(G)));
  }

  double max_log = 0., max_exp = 0., max_roundtrip = 0., max_symmetry = 0.;
  for (const auto &X : samples)
  {
    SymmetricTensor<4, 3>       dlog, dexp;
    const SymmetricTensor<2, 3> lnX = logarithm(X, &dlog);
    exponential(X, &dexp);
    max_roundtrip = std::max(max_roundtrip, (exponential(lnX) - X).norm() / X.norm());
    // the overload on a decomposition gives the same
    SymmetricTensor<4, 3> dexp_s;
    EXPECT_EQ(exponential(spectral_decomposition(X), &dexp_s), exponential(X));
    EXPECT_EQ(dexp_s, dexp);
    max_log = std::max(max_log, derivative_error(logarithm_value, X, dlog));
    max_exp = std::max(max_exp, derivative_error(exponential_value, X, dexp));
    // major symmetry (the derivative of an isotropic function is the Hessian of a potential)
    for (unsigned int p = 0; p < 6; ++p)
      for (unsigned int q = 0; q < 6; ++q)
        max_symmetry = std::max(
            max_symmetry,
            std::abs(dlog.access_raw_entry(6 * p + q) - dlog.access_raw_entry(6 * q + p)));
  }
  std::printf("[ tensor functions ] d ln / dX FD error %.2e, d exp / dX FD error %.2e, "
              "|exp(ln X) - X| / |X| %.2e\n",
              max_log,
              max_exp,
              max_roundtrip);
  EXPECT_LT(max_log, 1e-8);
  EXPECT_LT(max_exp, 1e-8);
  EXPECT_LT(max_roundtrip, 1e-14);
  EXPECT_EQ(max_symmetry, 0.); // assembled symmetric by construction

  // at X = I the derivative of ln is the symmetric identity
  SymmetricTensor<4, 3> dlog_I;
  logarithm(dealii::unit_symmetric_tensor<3>(), &dlog_I);
  EXPECT_LT((dlog_I - dealii::identity_tensor<3>()).norm(), 1e-14);
}

TEST(TensorFunctions, AddOuterProductEqualsDealIIOuterProduct)
{
  SymmetricTensor<2, 3> A, B;
  for (unsigned int i = 0; i < 3; ++i)
    for (unsigned int j = i; j < 3; ++j)
    {
      A[i][j] = 1. + i + 3. * j;
      B[i][j] = 0.5 - 2. * i + j * j;
    }
  SymmetricTensor<4, 3> D = dealii::identity_tensor<3>();
  add_outer_product(D, 0.7, A, B);
  const SymmetricTensor<4, 3> expected
      = dealii::identity_tensor<3>() + 0.7 * dealii::outer_product(A, B);
  EXPECT_LT((D - expected).norm(), 1e-14 * expected.norm());
}

TEST(TensorFunctions, PolarDecomposition)
{
  for (int sample = 0; sample < 20; ++sample)
  {
    // F = Q U with U = V diag(u) V^T, u in (0.5, 1.5); sample 0: two equal stretches
    const Tensor<2, 3>          Q = random_rotation(), V = random_rotation();
    const std::array<double, 3> u
        = {{1. + 0.5 * uniform(rng), sample == 0 ? 1.1 : 1. + 0.5 * uniform(rng), 1.1}};
    const SymmetricTensor<2, 3> U_exact = from_eigenpairs(V, u);
    const Tensor<2, 3>          F = Q * Tensor<2, 3>(U_exact);
    Tensor<2, 3>                R;
    SymmetricTensor<2, 3>       U;
    polar_decomposition(F, R, U);
    EXPECT_LT((R * Tensor<2, 3>(U) - F).norm() / F.norm(), 1e-14);
    EXPECT_LT((dealii::transpose(R) * R - Tensor<2, 3>(dealii::unit_symmetric_tensor<3>())).norm(),
              1e-14);
    EXPECT_NEAR(dealii::determinant(R), 1., 1e-14);
    EXPECT_LT((R - Q).norm(), 1e-13); // conditioned by 1 / (u_a + u_b) >= 1 / 3
    EXPECT_LT((U - U_exact).norm() / U_exact.norm(), 1e-14);
  }
}

TEST(TensorFunctions, PlaneDerivativesEqualTheGeneralOnesAndFiniteDifferences)
{
  // Plane tensors (e_3 principal: plane strain, axisymmetry) take the block path of the
  // derivative ({xx, yy, xy}, {zz}, {xz, yz}). Reference 1, the general path: the same tensor
  // turned out of the plane, X' = Q X Q^T (a generic rotation Q, so no eigenvector is a
  // coordinate axis), gives D' = Q^4 D for an isotropic function. Both are smooth functions of X
  // computed from the same divided differences; they differ by the rounding of the rotations
  // and of the eigenvectors (eps |X| / gap, but entering D only multiplied by the difference of
  // the divided differences, itself O(gap)): bound 1e-13 |D| (about 500 eps, the 3^4 sums of
  // rotate_4 included). Reference 2, central differences (h = 1e-6, bound 1e-8: the header).
  // In-plane eigenvalues split by 0 ... 0.3 and zz equal or nearly equal to one of them.
  double max_general = 0., max_fd = 0., max_coupling = 0.;
  for (const double split : {0., 1e-12, 1e-8, 1e-4, 0.3})
    for (const double zz : {0.7, 1.4, 1.4 + 1e-12, 1.4 + 1e-8, 1.4 + 1e-4})
      for (const double angle : {0., 0.4, 2.})
      {
        Tensor<2, 3> Q_plane; // a rotation about e_3
        Q_plane[0][0] = Q_plane[1][1] = std::cos(angle);
        Q_plane[0][1] = -std::sin(angle);
        Q_plane[1][0] = std::sin(angle);
        Q_plane[2][2] = 1.;
        SymmetricTensor<2, 3> X = from_eigenpairs(Q_plane, {{1.4 + split, 1.4, zz}});
        X[0][2] = X[1][2] = 0.; // exactly plane
        const Tensor<2, 3> Q = random_rotation();
        for (const bool exp : {false, true})
        {
          SymmetricTensor<4, 3> D, D_general;
          (exp ? exponential(X, &D) : logarithm(X, &D));
          const SymmetricTensor<2, 3> X_turned = rotate(Q, X);
          (exp ? exponential(X_turned, &D_general) : logarithm(X_turned, &D_general));
          const SymmetricTensor<4, 3> D_back
              = ausroll::testing::rotate_fourth_order(dealii::transpose(Q), D_general);
          double diff = 0., scale = 0.;
          for (unsigned int p = 0; p < 36; ++p)
          {
            diff = std::max(diff, std::abs(D.access_raw_entry(p) - D_back.access_raw_entry(p)));
            scale = std::max(scale, std::abs(D.access_raw_entry(p)));
          }
          max_general = std::max(max_general, diff / scale);
          // the blocks: no coupling of {xx, yy, zz, xy} with {xz, yz}, nor of zz with xx, yy, xy
          for (unsigned int p = 0; p < 6; ++p)
            for (unsigned int q = 0; q < 6; ++q)
              if ((p < 4) != (q < 4) || (p == 2) != (q == 2))
                max_coupling = std::max(max_coupling, std::abs(D.access_raw_entry(6 * p + q)));
          max_fd = std::max(max_fd,
                            exp ? derivative_error(exponential_value, X, D)
                                : derivative_error(logarithm_value, X, D));
        }
      }
  std::printf("[ tensor functions ] plane derivatives: against the general path %.2e |D|, "
              "FD error %.2e\n",
              max_general,
              max_fd);
  EXPECT_LT(max_general, 1e-13);
  EXPECT_LT(max_fd, 1e-8);
  EXPECT_EQ(max_coupling, 0.); // exact zeros, as the general loop gives for a plane tensor
}
