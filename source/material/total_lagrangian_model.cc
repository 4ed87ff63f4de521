#include <ausroll/material/total_lagrangian_model.h>

namespace ausroll::material
{
  using dealii::SymmetricTensor;
  using dealii::Tensor;

  TotalLagrangianModel::TotalLagrangianModel(std::unique_ptr<PlasticityModel> plasticity)
      : stress_return(std::move(plasticity))
  {
  }

  void TotalLagrangianModel::evaluate(const Tensor<2, 3>  &F,
                                      const MaterialState &old,
                                      MaterialState       &state,
                                      Tensor<2, 3>        &P,
                                      Tensor<4, 3>        *tangent) const
  {
    // Green-Lagrange strain E = (F^T F - I) / 2
    SymmetricTensor<2, 3> E;
    for (unsigned int I = 0; I < 3; ++I)
      for (unsigned int J = I; J < 3; ++J)
      {
        double c = 0.;
        for (unsigned int k = 0; k < 3; ++k)
          c += F[k][I] * F[k][J];
        E[I][J] = 0.5 * (c - (I == J ? 1. : 0.));
      }

    const SymmetricTensor<2, 3> trial_stress
        = stress_return->elasticity(old.temperature).stress(E - old.plastic_strain);
    const ReturnMappingResult    r = stress_return->return_map(trial_stress,
                                                            old.back_stress,
                                                            old.equivalent_plastic_strain,
                                                            old.temperature,
                                                            PhaseStep::of(old, state));
    const SymmetricTensor<2, 3> &S = r.stress;

    P = F * Tensor<2, 3>(S);

    // sigma = F S F^T / J = P F^T / J
    const double J = dealii::determinant(F);
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = i; j < 3; ++j)
      {
        double s = 0.;
        for (unsigned int K = 0; K < 3; ++K)
          s += P[i][K] * F[j][K];
        state.stress[i][j] = s / J;
      }
    state.plastic_strain = old.plastic_strain + r.plastic_strain_increment;
    state.back_stress = r.back_stress;
    state.equivalent_plastic_strain = old.equivalent_plastic_strain + r.eq_plastic_strain_increment;
    state.deformation_gradient = F;
    state.elastic_left_cauchy_green = old.elastic_left_cauchy_green;

    if (tangent == nullptr)
      return;

    // A_iJkL = delta_ik S_JL + sum_IK F_iI D_IJKL F_kK. First FD_iJKL = sum_I F_iI D_IJKL.
    const SymmetricTensor<4, 3> &D = r.tangent;
    double                       FD[3][3][3][3];
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int J = 0; J < 3; ++J)
        for (unsigned int K = 0; K < 3; ++K)
          for (unsigned int L = K; L < 3; ++L)
          {
            double s = 0.;
            for (unsigned int I = 0; I < 3; ++I)
              s += F[i][I] * D[I][J][K][L];
            FD[i][J][K][L] = FD[i][J][L][K] = s;
          }
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int J = 0; J < 3; ++J)
        for (unsigned int k = 0; k < 3; ++k)
          for (unsigned int L = 0; L < 3; ++L)
          {
            double s = (i == k) ? S[J][L] : 0.;
            for (unsigned int K = 0; K < 3; ++K)
              s += FD[i][J][K][L] * F[k][K];
            (*tangent)[i][J][k][L] = s;
          }
  }

  void TotalLagrangianModel::rebase(MaterialState &state, const Tensor<2, 3> &F) const
  {
    const Tensor<2, 3>          F_inv = dealii::invert(F);
    const SymmetricTensor<2, 3> S = dealii::symmetrize(
        dealii::determinant(F) * F_inv * Tensor<2, 3>(state.stress) * dealii::transpose(F_inv));
    const SymmetricTensor<2, 3> E
        = 0.5 * (dealii::symmetrize(dealii::transpose(F) * F) - dealii::unit_symmetric_tensor<3>());
    state.plastic_strain = E - stress_return->elasticity(state.temperature).strain(S);
    state.deformation_gradient = F;
  }

  double TotalLagrangianModel::yield_function(const MaterialState &state) const
  {
    const Tensor<2, 3>         &F = state.deformation_gradient;
    const Tensor<2, 3>          F_inv = dealii::invert(F);
    const SymmetricTensor<2, 3> S = dealii::symmetrize(
        dealii::determinant(F) * F_inv * Tensor<2, 3>(state.stress) * dealii::transpose(F_inv));
    return stress_return->yield_function(S,
                                         state.back_stress,
                                         state.equivalent_plastic_strain,
                                         state.temperature,
                                         PhaseStep::at(state));
  }

  void TotalLagrangianModel::make_admissible(MaterialState &state) const
  {
    const Tensor<2, 3>         &F = state.deformation_gradient;
    const double                J = dealii::determinant(F);
    const Tensor<2, 3>          F_inv = dealii::invert(F);
    const SymmetricTensor<2, 3> S
        = dealii::symmetrize(J * F_inv * Tensor<2, 3>(state.stress) * dealii::transpose(F_inv));
    const SymmetricTensor<2, 3> S_admissible
        = stress_return->project_onto_yield_surface(S,
                                                    state.back_stress,
                                                    state.equivalent_plastic_strain,
                                                    state.temperature,
                                                    PhaseStep::at(state));
    state.stress = dealii::symmetrize(F * Tensor<2, 3>(S_admissible) * dealii::transpose(F)) / J;
  }
} // namespace ausroll::material
