#include <ausroll/core/exceptions.h>
#include <ausroll/material/tensor_functions.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace ausroll::material
{
  using dealii::SymmetricTensor;
  using dealii::Tensor;

  namespace
  {
    using Vector = Tensor<1, 3>;

    /** a x b */
    inline Vector cross(const Vector &a, const Vector &b)
    {
      Vector c;
      c[0] = a[1] * b[2] - a[2] * b[1];
      c[1] = a[2] * b[0] - a[0] * b[2];
      c[2] = a[0] * b[1] - a[1] * b[0];
      return c;
    }

    /** A v for the symmetric 3x3 matrix @p A (full storage). */
    inline Vector multiply(const double (&A)[3][3], const Vector &v)
    {
      Vector w;
      for (unsigned int i = 0; i < 3; ++i)
        w[i] = A[i][0] * v[0] + A[i][1] * v[1] + A[i][2] * v[2];
      return w;
    }

    /**
     * One Jacobi rotation (Golub & Van Loan, Matrix Computations, 4th ed., Alg. 8.5.1) that
     * diagonalises the symmetric 2x2 matrix [b11 b12; b12 b22]: its eigenvalues are b11 - t b12
     * (eigenvector (c, -s)) and b22 + t b12 (eigenvector (s, c)). It gives the difference of the
     * two eigenvalues and an orthonormal pair of eigenvectors accurately whatever their distance
     * (equal eigenvalues, b12 = 0: no rotation).
     */
    struct JacobiRotation
    {
      double c = 1., s = 0., t = 0.;

      JacobiRotation(const double b11, const double b12, const double b22)
      {
        if (b12 != 0.)
        {
          const double theta = (b22 - b11) / (2. * b12); // +-inf for a tiny b12: t = 0
          t = (theta >= 0. ? 1. : -1.) / (std::abs(theta) + std::sqrt(1. + theta * theta));
          c = 1. / std::sqrt(1. + t * t);
          s = t * c;
        }
      }
    };

    /** Sorts the pairs (eta_a, v_a) by descending eta_a. */
    void sort_descending(double (&eta)[3], std::array<Vector, 3> &v)
    {
      for (unsigned int a = 0; a < 2; ++a)
        for (unsigned int b = 2; b > a; --b)
          if (eta[b] > eta[b - 1])
          {
            std::swap(eta[b], eta[b - 1]);
            std::swap(v[b], v[b - 1]);
          }
    }

    /**
     * Eigenvalues and orthonormal eigenvectors of a symmetric 3x3 matrix @p A with zero trace
     * and largest entry 1 in magnitude (so that nothing over- or underflows), after Scherzinger &
     * Dohrmann, "A robust algorithm for finding the eigenvalues and eigenvectors of 3x3 symmetric
     * matrices", Comput. Methods Appl. Mech. Engrg. 197 (2008) 4007-4015:
     *
     * 1. The eigenvalue farthest from the other two, eta_1, in closed form from the invariants J2
     *    and J3 (trigonometric solution of the characteristic cubic): with r = sqrt(J2 / 3) and
     *    cos 3 alpha = J3 / (2 r^3), alpha in [0, pi/3], it is 2 r cos(alpha) if alpha <= pi/6,
     *    else 2 r cos(alpha + 2 pi / 3). Its distance to the others is at least sqrt(J2) >= 0.7,
     *    so its eigenvector is well conditioned even when the other two coincide.
     * 2. Its eigenvector v_1 is orthogonal to the rows of A - eta_1 I, which span a plane: an
     *    orthonormal basis (u_1, u_2) of that plane from the longest row and the longest remaining
     *    part of another row (Gram-Schmidt), v_1 = u_1 x u_2.
     * 3. The other two pairs from the 2x2 matrix u_a . A u_b by one Jacobi rotation.
     *
     * The three eigenvalues are Rayleigh quotients of orthonormal vectors (the decomposition is
     * backward stable: V diag(eta) V^T = A + O(eps)).
     */
    void deviator_eigenpairs(const double (&A)[3][3], double (&eta)[3], std::array<Vector, 3> &v)
    {
      const double J2 = 0.5 * (A[0][0] * A[0][0] + A[1][1] * A[1][1] + A[2][2] * A[2][2])
                        + A[0][1] * A[0][1] + A[0][2] * A[0][2] + A[1][2] * A[1][2];
      const double J3 = A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[1][2])
                        - A[0][1] * (A[0][1] * A[2][2] - A[1][2] * A[0][2])
                        + A[0][2] * (A[0][1] * A[1][2] - A[1][1] * A[0][2]);
      const double r = std::sqrt(J2 / 3.); // J2 >= 1/2: the largest entry is 1
      const double cos_3alpha = std::clamp(0.5 * J3 / (r * r * r), -1., 1.);
      const double alpha = std::acos(cos_3alpha) / 3.;
      const double eta_1 = alpha <= M_PI / 6. ? 2. * r * std::cos(alpha)
                                              : 2. * r * std::cos(alpha + 2. * M_PI / 3.);

      // rows of A - eta_1 I; the longest one is the first basis vector of their plane
      Vector       row[3];
      double       length[3];
      unsigned int k = 0;
      for (unsigned int i = 0; i < 3; ++i)
      {
        for (unsigned int j = 0; j < 3; ++j)
          row[i][j] = A[i][j] - (i == j ? eta_1 : 0.);
        length[i] = row[i].norm_square();
        if (length[i] > length[k])
          k = i;
      }
      const Vector u1 = row[k] / std::sqrt(length[k]);
      // the longer of the other two rows without their part along u1
      const unsigned int i1 = (k + 1) % 3, i2 = (k + 2) % 3;
      const Vector       t1 = row[i1] - (row[i1] * u1) * u1;
      const Vector       t2 = row[i2] - (row[i2] * u1) * u1;
      const double       l1 = t1.norm_square(), l2 = t2.norm_square();
      Vector             v1 = cross(u1, l1 >= l2 ? t1 / std::sqrt(l1) : t2 / std::sqrt(l2));
      v1 /= v1.norm();
      const Vector u2 = cross(v1, u1); // orthonormal to v1 and u1 to round-off

      // the 2x2 problem in the plane (u1, u2)
      const Vector         Au1 = multiply(A, u1), Au2 = multiply(A, u2);
      const double         b11 = u1 * Au1, b22 = u2 * Au2, b12 = 0.5 * (u1 * Au2 + u2 * Au1);
      const JacobiRotation rotation(b11, b12, b22);
      eta[0] = v1 * multiply(A, v1);
      eta[1] = b11 - rotation.t * b12;
      eta[2] = b22 + rotation.t * b12;
      v[0] = v1;
      v[1] = rotation.c * u1 - rotation.s * u2;
      v[2] = rotation.s * u1 + rotation.c * u2;
    }

    /**
     * The eigenvalues of @p s from those of the scaled deviator, @p eta: all NaN if one is (so
     * that a NaN entry is never hidden behind a finite eigenvalue).
     */
    void set_values(const double (&eta)[3], const double scale, SpectralDecomposition &s)
    {
      const bool nan = std::isnan(eta[0] + eta[1] + eta[2]);
      for (unsigned int a = 0; a < 3; ++a)
      {
        s.shifted_values[a] = nan ? std::numeric_limits<double>::quiet_NaN() : scale * eta[a];
        s.values[a] = s.shifted_values[a] + s.shift;
      }
    }
  } // namespace

  SpectralDecomposition spectral_decomposition(const SymmetricTensor<2, 3> &X)
  {
    SpectralDecomposition s;
    s.shift = dealii::trace(X) / 3.;
    double A[3][3]; // the deviator
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        A[i][j] = X[i][j] - (i == j ? s.shift : 0.);
    double eta[3];

    // A coordinate axis e_i is an eigenvector if the off-diagonal entries of row i are zero (a
    // multiple of the identity, a diagonal tensor, and every plane-strain or axisymmetric
    // tensor, whose e_3 is principal): the other two pairs from one Jacobi rotation.
    for (unsigned int i = 0; i < 3; ++i)
    {
      const unsigned int j = (i + 1) % 3, k = (i + 2) % 3;
      if (A[i][j] == 0. && A[i][k] == 0.)
      {
        const JacobiRotation rotation(A[j][j], A[j][k], A[k][k]);
        eta[0] = A[i][i];
        eta[1] = A[j][j] - rotation.t * A[j][k];
        eta[2] = A[k][k] + rotation.t * A[j][k];
        for (unsigned int a = 0; a < 3; ++a)
          s.vectors[a] = Vector();
        s.vectors[0][i] = 1.;
        s.vectors[1][j] = rotation.c;
        s.vectors[1][k] = -rotation.s;
        s.vectors[2][j] = rotation.s;
        s.vectors[2][k] = rotation.c;
        sort_descending(eta, s.vectors);
        set_values(eta, 1., s);
        return s;
      }
    }

    // general case: the deviator scaled by its largest entry (NaN entries make the scale NaN)
    double scale = 0.;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = i; j < 3; ++j)
      {
        const double a = std::abs(A[i][j]);
        scale = a > scale || a != a ? a : scale;
      }
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        A[i][j] /= scale;
    deviator_eigenpairs(A, eta, s.vectors);
    sort_descending(eta, s.vectors);
    set_values(eta, scale, s);
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

  bool diagonal_in_eigenbasis(const SpectralDecomposition &s,
                              const SymmetricTensor<2, 3> &Y,
                              const double                 tolerance,
                              std::array<double, 3>       &y)
  {
    Tensor<1, 3> Yn[3];
    for (unsigned int a = 0; a < 3; ++a)
      Yn[a] = Y * s.vectors[a];
    if (std::abs(s.vectors[0] * Yn[1]) > tolerance || std::abs(s.vectors[0] * Yn[2]) > tolerance
        || std::abs(s.vectors[1] * Yn[2]) > tolerance)
      return false;
    for (unsigned int a = 0; a < 3; ++a)
      y[a] = s.vectors[a] * Yn[a];
    return true;
  }

  namespace
  {
    /**
     * The derivative of the isotropic function Y = sum_a f(x_a) n_a (x) n_a:
     * dY/dX = sum_{a,b} theta_ab N_ab (x) N_ab with N_ab = sym(n_a (x) n_b), theta_aa = f'(x_a)
     * and theta_ab = (f(x_a) - f(x_b)) / (x_a - x_b) (symmetric in a, b). Assembled on the 21
     * independent entries of the 6 x 6 raw storage of @p D (every entry is written; the result is
     * major symmetric).
     */
    void spectral_derivative(const SpectralDecomposition &s,
                             const double (&theta)[3][3],
                             SymmetricTensor<4, 3> &D)
    {
      // the raw index p of SymmetricTensor<2, 3> and its (i, j)
      static constexpr unsigned int first[6] = {0, 1, 2, 0, 0, 1};
      static constexpr unsigned int second[6] = {0, 1, 2, 1, 2, 2};
      double                        N[6][6]; // N[pair][p]
      double                        w[6];    // weight of each pair
      unsigned int                  pair = 0;
      for (unsigned int a = 0; a < 3; ++a)
        for (unsigned int b = a; b < 3; ++b, ++pair)
        {
          const Tensor<1, 3> &na = s.vectors[a], &nb = s.vectors[b];
          for (unsigned int p = 0; p < 6; ++p)
          {
            const unsigned int i = first[p], j = second[p];
            N[pair][p] = 0.5 * (na[i] * nb[j] + nb[i] * na[j]);
          }
          w[pair] = (a == b ? 1. : 2.) * theta[a][b];
        }

      // e_3 principal (a plane-strain or axisymmetric tensor: one eigenvector is +-e_3, the
      // others lie in the plane): N_ab has only xx, yy, xy entries for the two in-plane vectors,
      // only zz for e_3 (x) e_3 and only xz, yz for the mixed pairs, so dY/dX has the three
      // blocks {xx, yy, xy}, {zz}, {xz, yz}. The terms of each block are summed in the order of
      // the general loop (pairs ascending); the terms left out are products with exact zeros,
      // so the result is the general one to the bit.
      unsigned int axis = 3; // the index of the eigenvector +-e_3
      for (unsigned int a = 0; a < 3; ++a)
        if (s.vectors[a][0] == 0. && s.vectors[a][1] == 0.)
          axis = a;
      if (axis < 3 && s.vectors[(axis + 1) % 3][2] == 0. && s.vectors[(axis + 2) % 3][2] == 0.)
      {
        static constexpr unsigned int in_plane[3] = {0, 1, 3}, anti_plane[2] = {4, 5};
        for (unsigned int p = 0; p < 36; ++p)
          D.access_raw_entry(p) = 0.;
        pair = 0;
        for (unsigned int a = 0; a < 3; ++a)
          for (unsigned int b = a; b < 3; ++b, ++pair)
          {
            const auto add = [&](const auto &entries)
            {
              for (const unsigned int p : entries)
                for (const unsigned int q : entries)
                  if (q >= p)
                    D.access_raw_entry(6 * p + q) += w[pair] * N[pair][p] * N[pair][q];
            };
            if (a != axis && b != axis)
              add(in_plane);
            else if (a == axis && b == axis)
              D.access_raw_entry(6 * 2 + 2) += w[pair] * N[pair][2] * N[pair][2];
            else
              add(anti_plane);
          }
        for (unsigned int p = 0; p < 6; ++p)
          for (unsigned int q = p + 1; q < 6; ++q)
            D.access_raw_entry(6 * q + p) = D.access_raw_entry(6 * p + q);
        return;
      }

      for (unsigned int p = 0; p < 6; ++p)
        for (unsigned int q = p; q < 6; ++q)
        {
          double d = 0.;
          for (unsigned int k = 0; k < 6; ++k)
            d += w[k] * N[k][p] * N[k][q];
          D.access_raw_entry(6 * p + q) = d;
          D.access_raw_entry(6 * q + p) = d;
        }
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
      spectral_derivative(s, theta, *derivative);
    }
    return spectral_sum(s, f);
  }

  SymmetricTensor<2, 3> exponential(const SymmetricTensor<2, 3> &X,
                                    SymmetricTensor<4, 3>       *derivative)
  {
    return exponential(spectral_decomposition(X), derivative);
  }

  SymmetricTensor<2, 3> exponential(const SpectralDecomposition &s,
                                    SymmetricTensor<4, 3>       *derivative)
  {
    std::array<double, 3> f;
    for (unsigned int a = 0; a < 3; ++a)
      f[a] = std::exp(s.values[a]);
    if (derivative != nullptr)
    {
      // (e^x_a - e^x_b) / (x_a - x_b) = e^x_b expm1(d) / d with d = x_a - x_b
      double theta[3][3];
      for (unsigned int a = 0; a < 3; ++a)
        for (unsigned int b = a; b < 3; ++b)
          theta[a][b] = theta[b][a] = f[b] * expm1_over(s.shifted_values[a] - s.shifted_values[b]);
      spectral_derivative(s, theta, *derivative);
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
