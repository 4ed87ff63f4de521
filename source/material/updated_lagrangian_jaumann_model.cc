#include <ausroll/material/tensor_functions.h>
#include <ausroll/material/updated_lagrangian_jaumann_model.h>

namespace ausroll::material
{
  using dealii::SymmetricTensor;
  using dealii::Tensor;

  UpdatedLagrangianJaumannModel::UpdatedLagrangianJaumannModel(
      std::unique_ptr<PlasticityModel> plasticity)
      : stress_return(std::move(plasticity))
  {
  }

  namespace
  {
    /** d(Q X Q^T) = dQ X Q^T + Q X dQ^T for symmetric X, given XQt = X Q^T. */
    SymmetricTensor<2, 3> rotation_rate(const Tensor<2, 3> &dQ, const Tensor<2, 3> &XQt)
    {
      const Tensor<2, 3>    Y = dQ * XQt;
      SymmetricTensor<2, 3> result;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = i; j < 3; ++j)
          result[i][j] = Y[i][j] + Y[j][i];
      return result;
    }
  } // namespace

  void UpdatedLagrangianJaumannModel::evaluate(const Tensor<2, 3>  &F,
                                               const MaterialState &old,
                                               MaterialState       &state,
                                               Tensor<2, 3>        &P,
                                               Tensor<4, 3>        *tangent) const
  {
    const Tensor<2, 3> &F_n = old.deformation_gradient;
    const Tensor<2, 3>  I = dealii::unit_symmetric_tensor<3>();

    // incremental displacement gradient w.r.t. the midpoint configuration
    const Tensor<2, 3> F_mid_inv = dealii::invert(0.5 * (F + F_n));
    const Tensor<2, 3> dL = (F - F_n) * F_mid_inv;
    const Tensor<2, 3> dW = 0.5 * (dL - dealii::transpose(dL));
    const Tensor<2, 3> M = dealii::invert(I - 0.5 * dW);
    const Tensor<2, 3> Q = M * (I + 0.5 * dW);

    const SymmetricTensor<2, 3> d_eps = dealii::symmetrize(dL);
    const SymmetricTensor<2, 3> trial_stress
        = rotate(Q, old.stress) + stress_return->elasticity().stress(d_eps);
    const SymmetricTensor<2, 3> trial_back_stress = rotate(Q, old.back_stress);
    const ReturnMappingResult   r
        = stress_return->return_map(trial_stress, trial_back_stress, old.equivalent_plastic_strain);

    state.stress = r.stress;
    state.plastic_strain = rotate(Q, old.plastic_strain) + r.plastic_strain_increment;
    state.back_stress = r.back_stress;
    state.equivalent_plastic_strain = old.equivalent_plastic_strain + r.eq_plastic_strain_increment;
    state.deformation_gradient = F;
    state.elastic_left_cauchy_green = old.elastic_left_cauchy_green;

    // P = J sigma F^-T
    const double       J = dealii::determinant(F);
    const Tensor<2, 3> F_inv = dealii::invert(F);
    P = J * (Tensor<2, 3>(r.stress) * dealii::transpose(F_inv));

    if (tangent == nullptr)
      return;

    const IsotropicElasticity  &elastic = stress_return->elasticity();
    const Tensor<2, 3>          I_minus_half_dL = I - 0.5 * dL;
    const Tensor<2, 3>          Q_plus_I = Q + I;
    const Tensor<2, 3>          stress_Qt = Tensor<2, 3>(old.stress) * dealii::transpose(Q);
    const Tensor<2, 3>          back_Qt = Tensor<2, 3>(old.back_stress) * dealii::transpose(Q);
    const bool                  rotate_back_stress = old.back_stress.norm() > 0.;
    const SymmetricTensor<4, 3> back_sensitivity
        = rotate_back_stress ? stress_return->back_stress_sensitivity(r) : SymmetricTensor<4, 3>();

    for (unsigned int k = 0; k < 3; ++k)
      for (unsigned int L = 0; L < 3; ++L)
      {
        // dF = e_k (x) e_L: d Delta L = (I - Delta L / 2) dF F_mid^-1 = a (x) b
        Tensor<2, 3> ddL;
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            ddL[i][j] = I_minus_half_dL[i][k] * F_mid_inv[L][j];
        const Tensor<2, 3> ddW = 0.5 * (ddL - dealii::transpose(ddL));
        const Tensor<2, 3> dQ = 0.5 * (M * ddW * Q_plus_I);

        // d eps_e_trial = C^-1 : d(Q sigma_n Q^T) + d Delta eps
        const SymmetricTensor<2, 3> d_strain
            = elastic.strain(rotation_rate(dQ, stress_Qt)) + dealii::symmetrize(ddL);
        SymmetricTensor<2, 3> d_sigma = r.tangent * d_strain;
        if (rotate_back_stress)
          d_sigma += back_sensitivity * rotation_rate(dQ, back_Qt);

        // dP = J tr(F^-1 dF) sigma F^-T + J d_sigma F^-T - J sigma F^-T dF^T F^-T
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int Jj = 0; Jj < 3; ++Jj)
          {
            double s = 0.;
            for (unsigned int j = 0; j < 3; ++j)
              s += d_sigma[i][j] * F_inv[Jj][j];
            (*tangent)[i][Jj][k][L] = J * s + P[i][Jj] * F_inv[L][k] - P[i][L] * F_inv[Jj][k];
          }
      }
  }
} // namespace ausroll::material
