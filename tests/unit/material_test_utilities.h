/**
 * @file material_test_utilities.h
 * Helpers shared by the material unit tests.
 */
#pragma once

#include <ausroll/material/constitutive_model.h>

#include <deal.II/base/tensor.h>

#include <algorithm>
#include <cmath>

namespace ausroll::testing
{
  /**
   * Central finite-difference check of A = dP/dF of @p model at @p F for the committed state
   * @p old: max |A_fd - A| / max |A| with h = 1e-7 (truncation ~1e-12, round-off ~1e-9 relative),
   * over the components i, j, k, l < @p n (3: all; 2: the in-plane block).
   */
  inline double tangent_error(const material::ConstitutiveModel &model,
                              const material::MaterialState     &old,
                              const dealii::Tensor<2, 3>        &F,
                              const unsigned int                 n = 3)
  {
    material::MaterialState trial;
    dealii::Tensor<2, 3>    P;
    dealii::Tensor<4, 3>    A;
    model.evaluate(F, old, trial, P, &A);
    const double h = 1e-7;
    double       max_err = 0., scale = 0.;
    for (unsigned int k = 0; k < n; ++k)
      for (unsigned int l = 0; l < n; ++l)
      {
        dealii::Tensor<2, 3> Fp = F, Fm = F, Pp, Pm;
        Fp[k][l] += h;
        Fm[k][l] -= h;
        model.evaluate(Fp, old, trial, Pp, nullptr);
        model.evaluate(Fm, old, trial, Pm, nullptr);
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
          {
            const double fd = (Pp[i][j] - Pm[i][j]) / (2. * h);
            max_err = std::max(max_err, std::abs(fd - A[i][j][k][l]));
            scale = std::max(scale, std::abs(A[i][j][k][l]));
          }
      }
    return max_err / scale;
  }

  /**
   * R_ijkl = Q_ia Q_jb Q_kc Q_ld D_abcd: a fourth-order tensor (Tensor<4, 3> or
   * SymmetricTensor<4, 3>) in the frame turned by @p Q.
   */
  template <typename Tensor4>
  Tensor4 rotate_fourth_order(const dealii::Tensor<2, 3> &Q, const Tensor4 &D)
  {
    Tensor4 R;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        for (unsigned int k = 0; k < 3; ++k)
          for (unsigned int l = 0; l < 3; ++l)
          {
            double sum = 0.;
            for (unsigned int a = 0; a < 3; ++a)
              for (unsigned int b = 0; b < 3; ++b)
                for (unsigned int c = 0; c < 3; ++c)
                  for (unsigned int d = 0; d < 3; ++d)
                    sum += Q[i][a] * Q[j][b] * Q[k][c] * Q[l][d] * D[a][b][c][d];
            R[i][j][k][l] = sum;
          }
    return R;
  }

  /** As tangent_error() for a plane-stress model (PlaneStressDriver sets F_zz itself): the
      in-plane block of dP/dF against central differences of the in-plane components of F. */
  inline double in_plane_tangent_error(const material::ConstitutiveModel &model,
                                       const material::MaterialState     &old,
                                       const dealii::Tensor<2, 3>        &F)
  {
    return tangent_error(model, old, F, 2);
  }
} // namespace ausroll::testing
