#include <ausroll/material/small_strain_model.h>

namespace ausroll::material
{
  using dealii::SymmetricTensor;
  using dealii::Tensor;

  SmallStrainModel::SmallStrainModel(std::unique_ptr<PlasticityModel> plasticity)
      : stress_return(std::move(plasticity))
  {
  }

  void SmallStrainModel::evaluate(const Tensor<2, 3>  &F,
                                  const MaterialState &old,
                                  MaterialState       &state,
                                  Tensor<2, 3>        &P,
                                  Tensor<4, 3>        *tangent) const
  {
    const SymmetricTensor<2, 3> strain = dealii::symmetrize(F) - dealii::unit_symmetric_tensor<3>();
    const SymmetricTensor<2, 3> trial_stress
        = stress_return->elasticity(old.temperature).stress(strain - old.plastic_strain);
    const ReturnMappingResult r = stress_return->return_map(trial_stress,
                                                            old.back_stress,
                                                            old.equivalent_plastic_strain,
                                                            old.temperature,
                                                            PhaseStep::of(old, state));

    state.stress = r.stress;
    state.plastic_strain = old.plastic_strain + r.plastic_strain_increment;
    state.back_stress = r.back_stress;
    state.equivalent_plastic_strain = old.equivalent_plastic_strain + r.eq_plastic_strain_increment;
    state.deformation_gradient = F;
    state.elastic_left_cauchy_green = old.elastic_left_cauchy_green;

    P = r.stress;
    if (tangent != nullptr)
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          for (unsigned int k = 0; k < 3; ++k)
            for (unsigned int l = 0; l < 3; ++l)
              (*tangent)[i][j][k][l] = r.tangent[i][j][k][l];
  }

  void SmallStrainModel::rebase(MaterialState &state, const Tensor<2, 3> &F) const
  {
    state.plastic_strain = dealii::symmetrize(F) - dealii::unit_symmetric_tensor<3>()
                           - stress_return->elasticity(state.temperature).strain(state.stress);
    state.deformation_gradient = F;
  }
} // namespace ausroll::material
