#include <ausroll/core/exceptions.h>
#include <ausroll/material/tensor_functions.h>

#include <cmath>
#include <sstream>

namespace ausroll::material
{
  using dealii::SymmetricTensor;
  using dealii::Tensor;

  SpectralDecomposition spectral_decomposition(const SymmetricTensor<2, 3> &X)
  {
    SpectralDecomposition s;
    s.shift = dealii::trace(X) / 3.;
    SymmetricTensor<2, 3> deviator = X;
    for (unsigned int i = 0; i < 3; ++i)
      deviator[i][i] -= s.shift;
    const auto eigen = dealii::eigenvectors(
        deviator, dealii::SymmetricTensorEigenvectorMethod::ql_implicit_shifts);
    for (unsigned int a = 0; a < 3; ++a)
    {
      s.shifted_values[a] = eigen[a].first;
      s.values[a] = eigen[a].first + s.shift;
      s.vectors[a] = eigen[a].second;
    }
    return s;
  }

  SymmetricTensor<2, 3> spectral_sum(const SpectralDecomposition &s, const std::array<double, 3> &f)
  {
    SymmetricTensor<2, 3> Y;
    for (unsigned int a = 0; a < 3; ++a)
    {
      const Tensor<1, 3> &n = s.vectors[a];
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = i; j < 3; ++j)
          Y[i][j] += f[a] * n[i] * n[j];
    }
    return Y;
  }

  namespace
  {
    /**
     * The derivative of the isotropic function Y = sum_a f(x_a) n_a (x) n_a:
     * dY/dX = sum_{a,b} theta_ab N_ab (x) N_ab with N_ab = sym(n_a (x) n_b), theta_aa = f'(x_a)
     * and theta_ab = (f(x_a) - f(x_b)) / (x_a - x_b) (symmetric in a, b).
     */
    SymmetricTensor<4, 3> spectral_derivative(const SpectralDecomposition &s,
                                              const double (&theta)[3][3])
    {
      SymmetricTensor<4, 3> D;
      for (unsigned int a = 0; a < 3; ++a)
        for (unsigned int b = a; b < 3; ++b)
        {
          SymmetricTensor<2, 3> N;
          for (unsigned int i = 0; i < 3; ++i)
            for (unsigned int j = i; j < 3; ++j)
              N[i][j]
                  = 0.5 * (s.vectors[a][i] * s.vectors[b][j] + s.vectors[b][i] * s.vectors[a][j]);
          add_outer_product(D, (a == b ? 1. : 2.) * theta[a][b], N, N);
        }
      return D;
    }

    /** log1p(d) / d, accurate for all d > -1 including d -> 0. */
    double log1p_over(const double d)
    {
      if (std::abs(d) < 1e-8)
        return 1. - d * (0.5 - d / 3.);
      return std::log1p(d) / d;
    }

    /** expm1(d) / d, accurate for all d including d -> 0. */
    double expm1_over(const double d)
    {
      if (std::abs(d) < 1e-8)
        return 1. + d * (0.5 + d / 6.);
      return std::expm1(d) / d;
    }
  } // namespace

  SymmetricTensor<2, 3> logarithm(const SymmetricTensor<2, 3> &X, SymmetricTensor<4, 3> *derivative)
  {
    return logarithm(spectral_decomposition(X), derivative);
  }

  SymmetricTensor<2, 3> logarithm(const SpectralDecomposition &s, SymmetricTensor<4, 3> *derivative)
  {
    std::array<double, 3> f;
    for (unsigned int a = 0; a < 3; ++a)
    {
      if (!(s.values[a] > 0.))
      {
        std::ostringstream msg;
        msg << "logarithm of a tensor that is not positive definite (eigenvalue " << s.values[a]
            << ")";
        throw RunFailure(msg.str());
      }
      f[a] = std::log(s.values[a]);
    }
    if (derivative != nullptr)
    {
      // (ln x_a - ln x_b) / (x_a - x_b) = log1p(d) / d / x_b with d = (x_a - x_b) / x_b; the
      // difference x_a - x_b is taken from the shifted eigenvalues.
      double theta[3][3];
      for (unsigned int a = 0; a < 3; ++a)
        for (unsigned int b = a; b < 3; ++b)
        {
          const double d = (s.shifted_values[a] - s.shifted_values[b]) / s.values[b];
          theta[a][b] = theta[b][a] = log1p_over(d) / s.values[b];
        }
      *derivative = spectral_derivative(s, theta);
    }
    return spectral_sum(s, f);
  }

  SymmetricTensor<2, 3> exponential(const SymmetricTensor<2, 3> &X,
                                    SymmetricTensor<4, 3>       *derivative)
  {
    const SpectralDecomposition s = spectral_decomposition(X);
    std::array<double, 3>       f;
    for (unsigned int a = 0; a < 3; ++a)
      f[a] = std::exp(s.values[a]);
    if (derivative != nullptr)
    {
      // (e^x_a - e^x_b) / (x_a - x_b) = e^x_b expm1(d) / d with d = x_a - x_b
      double theta[3][3];
      for (unsigned int a = 0; a < 3; ++a)
        for (unsigned int b = a; b < 3; ++b)
          theta[a][b] = theta[b][a] = f[b] * expm1_over(s.shifted_values[a] - s.shifted_values[b]);
      *derivative = spectral_derivative(s, theta);
    }
    return spectral_sum(s, f);
  }

  void polar_decomposition(const Tensor<2, 3> &F, Tensor<2, 3> &R, SymmetricTensor<2, 3> &U)
  {
    const SpectralDecomposition s
        = spectral_decomposition(dealii::symmetrize(dealii::transpose(F) * F));
    std::array<double, 3> u, u_inv;
    for (unsigned int a = 0; a < 3; ++a)
    {
      if (!(s.values[a] > 0.))
        throw RunFailure("polar decomposition of a singular deformation gradient");
      u[a] = std::sqrt(s.values[a]);
      u_inv[a] = 1. / u[a];
    }
    U = spectral_sum(s, u);
    R = F * Tensor<2, 3>(spectral_sum(s, u_inv));
  }
} // namespace ausroll::material
