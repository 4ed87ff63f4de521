/**
 * @file tensor_functions.h
 * Isotropic functions of symmetric 3x3 tensors (logarithm, exponential) and their derivatives
 * through the spectral decomposition, and the polar decomposition. For a tensor with e_3
 * principal (plane strain, axisymmetry) the derivatives are assembled on their three blocks
 * ({xx, yy, xy}, {zz}, {xz, yz}) only. Used by the finite-strain
 * material models (`Model/Kinematics = finite strain`); no state, no allocation.
 */
#pragma once

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <array>

namespace ausroll::material
{
  /**
   * Eigenvalues and orthonormal eigenvectors of a symmetric 3x3 tensor X = sum_a x_a n_a (x) n_a.
   * The decomposition is computed for the deviator X - s I with s = tr X / 3 (so that the
   * eigenvalue differences, which the derivatives divide by, are accurate also for X close to a
   * multiple of the identity); @ref shifted_values keeps x_a - s. When eigenvalues coincide, the
   * eigenvectors are one orthonormal basis of their eigenspace (any is right for an isotropic
   * function).
   */
  struct SpectralDecomposition
  {
    std::array<double, 3>               values;         ///< eigenvalues x_a (descending)
    std::array<double, 3>               shifted_values; ///< x_a - shift
    double                              shift = 0.;     ///< tr X / 3
    std::array<dealii::Tensor<1, 3>, 3> vectors;        ///< unit eigenvectors n_a
  };

  /**
   * Spectral decomposition of @p X in closed form (Scherzinger & Dohrmann 2008: the most distinct
   * eigenvalue from the invariants, its eigenvector from cross products, the other two by one
   * Jacobi rotation; robust for equal and nearly equal eigenvalues, no iteration). A NaN entry
   * gives NaN eigenvalues.
   */
  SpectralDecomposition spectral_decomposition(const dealii::SymmetricTensor<2, 3> &X);

  /** sum_a f_a n_a (x) n_a for the eigenvectors n_a of @p s (an isotropic function's value). */
  dealii::SymmetricTensor<2, 3> spectral_sum(const SpectralDecomposition &s,
                                             const std::array<double, 3> &f);

  /**
   * The diagonal entries y_a = n_a . Y n_a of @p Y in the eigenbasis n_a of @p s, if its
   * off-diagonal entries n_a . Y n_b (a != b) are at most @p tolerance in magnitude; returns
   * false (and leaves @p y unspecified) otherwise. Then Y = sum_a y_a n_a (x) n_a up to those
   * entries, and an isotropic function of Y reuses the eigenvectors of @p s (spectral_sum()).
   */
  bool diagonal_in_eigenbasis(const SpectralDecomposition         &s,
                              const dealii::SymmetricTensor<2, 3> &Y,
                              double                               tolerance,
                              std::array<double, 3>               &y);

  /**
   * The matrix logarithm ln X of a symmetric positive definite @p X; if @p derivative is not null,
   * also d ln X / d X (minor- and major-symmetric; ln(X + dX) = ln X + derivative : dX for
   * symmetric dX). The derivative uses the divided differences (ln x_a - ln x_b) / (x_a - x_b),
   * evaluated stably (log1p) so that equal or nearly equal eigenvalues give the limit 1 / x.
   * Throws RunFailure if X is not positive definite.
   */
  dealii::SymmetricTensor<2, 3> logarithm(const dealii::SymmetricTensor<2, 3> &X,
                                          dealii::SymmetricTensor<4, 3> *derivative = nullptr);

  /** As logarithm(X, derivative), for the already computed decomposition @p s of X. */
  dealii::SymmetricTensor<2, 3> logarithm(const SpectralDecomposition   &s,
                                          dealii::SymmetricTensor<4, 3> *derivative = nullptr);

  /**
   * The matrix exponential exp X of a symmetric @p X and, if @p derivative is not null,
   * d exp X / d X (divided differences (e^x_a - e^x_b) / (x_a - x_b) via expm1; limit e^x).
   */
  dealii::SymmetricTensor<2, 3> exponential(const dealii::SymmetricTensor<2, 3> &X,
                                            dealii::SymmetricTensor<4, 3> *derivative = nullptr);

  /** As exponential(X, derivative), for the already computed decomposition @p s of X. */
  dealii::SymmetricTensor<2, 3> exponential(const SpectralDecomposition   &s,
                                            dealii::SymmetricTensor<4, 3> *derivative = nullptr);

  /**
   * Right polar decomposition F = R U of a tensor with det F > 0 (R a rotation, U = sqrt(F^T F)
   * symmetric positive definite). Throws RunFailure if F^T F is not positive definite.
   */
  void polar_decomposition(const dealii::Tensor<2, 3>    &F,
                           dealii::Tensor<2, 3>          &R,
                           dealii::SymmetricTensor<2, 3> &U);

  /**
   * D += w A (x) B on the 6 x 6 independent entries (the same as
   * D += w * dealii::outer_product(A, B), without the temporary and the index mapping of
   * SymmetricTensor<4>::operator[]; used in the hot path of the material models).
   */
  inline void add_outer_product(dealii::SymmetricTensor<4, 3>       &D,
                                const double                         w,
                                const dealii::SymmetricTensor<2, 3> &A,
                                const dealii::SymmetricTensor<2, 3> &B)
  {
    for (unsigned int p = 0; p < 6; ++p)
    {
      const double wa = w * A.access_raw_entry(p);
      for (unsigned int q = 0; q < 6; ++q)
        D.access_raw_entry(6 * p + q) += wa * B.access_raw_entry(q);
    }
  }

  /** The axial vector w of the skew part of @p W: skew(W) v = w x v. */
  inline dealii::Tensor<1, 3> axial_vector(const dealii::Tensor<2, 3> &W)
  {
    dealii::Tensor<1, 3> w;
    w[0] = 0.5 * (W[2][1] - W[1][2]);
    w[1] = 0.5 * (W[0][2] - W[2][0]);
    w[2] = 0.5 * (W[1][0] - W[0][1]);
    return w;
  }

  /** The skew tensor W with W v = @p w x v. */
  inline dealii::Tensor<2, 3> skew_from_axial(const dealii::Tensor<1, 3> &w)
  {
    dealii::Tensor<2, 3> W;
    W[0][1] = -w[2];
    W[1][0] = w[2];
    W[0][2] = w[1];
    W[2][0] = -w[1];
    W[1][2] = -w[0];
    W[2][1] = w[0];
    return W;
  }

  /** Q X Q^T for a symmetric @p X (exactly symmetric result). */
  inline dealii::SymmetricTensor<2, 3> rotate(const dealii::Tensor<2, 3>          &Q,
                                              const dealii::SymmetricTensor<2, 3> &X)
  {
    const dealii::Tensor<2, 3>    QX = Q * dealii::Tensor<2, 3>(X);
    dealii::SymmetricTensor<2, 3> result;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = i; j < 3; ++j)
      {
        double s = 0.;
        for (unsigned int k = 0; k < 3; ++k)
          s += QX[i][k] * Q[j][k];
        result[i][j] = s;
      }
    return result;
  }
} // namespace ausroll::material
