/**
 * @file small_strain_model.h
 * Infinitesimal-strain elastic-plastic model (`Model/Kinematics = small strain`).
 */
#pragma once

#include <ausroll/material/constitutive_model.h>

namespace ausroll::material
{
  /**
   * eps = sym(F) - I, sigma = C : (eps - eps_p), plasticity by the PlasticityModel's return map.
   * P = sigma and A = D_alg (minor-symmetric, so dP/dF = D_alg). The mesh stays in the reference
   * configuration.
   */
  class SmallStrainModel : public ConstitutiveModel
  {
  public:
    /** Model owning the stress return @p plasticity. */
    explicit SmallStrainModel(std::unique_ptr<PlasticityModel> plasticity);

    void evaluate(const dealii::Tensor<2, 3> &F,
                  const MaterialState        &old,
                  MaterialState              &state,
                  dealii::Tensor<2, 3>       &P,
                  dealii::Tensor<4, 3>       *tangent) const override;

    bool is_small_strain() const override { return true; }

    /** Keep the stress: eps_p = eps(F) - C^-1 : sigma. */
    void rebase(MaterialState &state, const dealii::Tensor<2, 3> &F) const override;

    const PlasticityModel &plasticity() const override { return *stress_return; }

  private:
    std::unique_ptr<PlasticityModel> stress_return; ///< return mapping
  };
} // namespace ausroll::material
