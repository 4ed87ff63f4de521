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

    // half-step rotation (Cayley transform of Delta W / 4): the elastic stress increment is
    // rotated to the end of the step from the middle of the step, where Delta eps is evaluated
    const Tensor<2, 3> M_half = dealii::invert(I - 0.25 * dW);
    const Tensor<2, 3> Q_half = M_half * (I + 0.25 * dW);

    const SymmetricTensor<2, 3> d_eps = dealii::symmetrize(dL);
    const SymmetricTensor<2, 3> d_stress = stress_return->elasticity(old.temperature).stress(d_eps);
    const SymmetricTensor<2, 3> trial_stress = rotate(Q, old.stress) + rotate(Q_half, d_stress);
    const SymmetricTensor<2, 3> trial_back_stress = rotate(Q, old.back_stress);
    const ReturnMappingResult   r = stress_return->return_map(trial_stress,
                                                            trial_back_stress,
                                                            old.equivalent_plastic_strain,
                                                            old.temperature,
                                                            PhaseStep::of(old, state));

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

    // Direction dF = e_k (x) e_L: d Delta L = (I - Delta L / 2) dF F_mid^-1 = a_k (x) b_L with
    // a_k = column k of (I - Delta L / 2), b_L = row L of F_mid^-1; d Delta W = (a (x) b - b (x) a)
    // / 2 and dQ = M d Delta W (Q + I) / 2, so for a symmetric X with V = (Q + I) X Q^T d(Q X Q^T)
    // = dQ X Q^T + (..)^T = 2 sym[(M a) (x) (V^T b) - (M b) (x) (V^T a)] / 4, a sum of rank-one
    // terms built from vectors precomputed per k and per L.
    const IsotropicElasticity elastic = stress_return->elasticity(old.temperature);
    const Tensor<2, 3>        a_vectors = dealii::transpose(I - 0.5 * dL); // row k = a_k
    const Tensor<2, 3>       &b_vectors = F_mid_inv;                       // row L = b_L
    const Tensor<2, 3>        Q_plus_I = Q + I;
    const Tensor<2, 3>        Vt_stress
        = dealii::transpose(Q_plus_I * Tensor<2, 3>(old.stress) * dealii::transpose(Q));
    // the same for the rotated strain-increment stress C : Delta eps, whose rotation is
    // Q_half (..) Q_half^T with d Q_half = M_half d Delta W (Q_half + I) / 4 (half the rate)
    const Tensor<2, 3> Vt_increment
        = dealii::transpose((Q_half + I) * Tensor<2, 3>(d_stress) * dealii::transpose(Q_half));
    const bool         rotate_back_stress = old.back_stress.norm() > 0.;
    const Tensor<2, 3> Vt_back
        = rotate_back_stress
              ? dealii::transpose(Q_plus_I * Tensor<2, 3>(old.back_stress) * dealii::transpose(Q))
              : Tensor<2, 3>();
    const SymmetricTensor<4, 3> back_sensitivity
        = rotate_back_stress ? stress_return->back_stress_sensitivity(r, old.temperature)
                             : SymmetricTensor<4, 3>();

    Tensor<1, 3> Ma[3], Mb[3], Va[3], Vb[3], Wa[3], Wb[3]; // M a, M b, V^T a, V^T b (stress, back)
    Tensor<1, 3> Ha[3], Hb[3], Za[3], Zb[3]; // M_half a, M_half b, V_inc^T a, V_inc^T b
    Tensor<1, 3> Qa[3], Qb[3];               // Q_half a, Q_half b
    for (unsigned int k = 0; k < 3; ++k)
    {
      Ma[k] = M * a_vectors[k];
      Mb[k] = M * b_vectors[k];
      Va[k] = Vt_stress * a_vectors[k];
      Vb[k] = Vt_stress * b_vectors[k];
      Ha[k] = M_half * a_vectors[k];
      Hb[k] = M_half * b_vectors[k];
      Za[k] = Vt_increment * a_vectors[k];
      Zb[k] = Vt_increment * b_vectors[k];
      Qa[k] = Q_half * a_vectors[k];
      Qb[k] = Q_half * b_vectors[k];
      if (rotate_back_stress)
      {
        Wa[k] = Vt_back * a_vectors[k];
        Wb[k] = Vt_back * b_vectors[k];
      }
    }
    auto rotation_rate = [](const Tensor<1, 3> &ma,
                            const Tensor<1, 3> &vb,
                            const Tensor<1, 3> &mb,
                            const Tensor<1, 3> &va)
    {
      SymmetricTensor<2, 3> rate;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = i; j < 3; ++j)
          rate[i][j] = 0.25 * (ma[i] * vb[j] + vb[i] * ma[j] - mb[i] * va[j] - va[i] * mb[j]);
      return rate;
    };

    for (unsigned int k = 0; k < 3; ++k)
      for (unsigned int L = 0; L < 3; ++L)
      {
        // d eps_e_trial = C^-1 : [d(Q sigma_n Q^T) + d(Q_half) (C : Delta eps) Q_half^T + (..)^T]
        //                + Q_half d Delta eps Q_half^T, d Delta eps = sym(a_k (x) b_L) (C is
        //                isotropic, so Q_half (C : X) Q_half^T = C : (Q_half X Q_half^T))
        SymmetricTensor<2, 3> d_strain
            = elastic.strain(rotation_rate(Ma[k], Vb[L], Mb[L], Va[k])
                             + 0.5 * rotation_rate(Ha[k], Zb[L], Hb[L], Za[k]));
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = i; j < 3; ++j)
            d_strain[i][j] += 0.5 * (Qa[k][i] * Qb[L][j] + Qa[k][j] * Qb[L][i]);
        SymmetricTensor<2, 3> d_sigma = r.tangent * d_strain;
        if (rotate_back_stress)
          d_sigma += back_sensitivity * rotation_rate(Ma[k], Wb[L], Mb[L], Wa[k]);

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
