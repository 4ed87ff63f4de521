/**
 * @file total_lagrangian_model.h
 * Total Lagrangian elastic-plastic model (`Model/Kinematics = total Lagrangian`).
 */
#pragma once

#include <ausroll/material/constitutive_model.h>

namespace ausroll::material
{
  /**
   * Total Lagrangian J2 plasticity, additive in the Green-Lagrange strain (as the TL formulation
   * of NOFEAP / Bathe): E = (F^T F - I) / 2, second Piola-Kirchhoff stress S = C : (E - E_p), the
   * return mapping of the PlasticityModel done in (S, E) space with the back stress in S space.
   * P = F S, Cauchy stress sigma = F S F^T / J. Exact tangent
   * A_iJkL = delta_ik S_JL + F_iI D_IJKL F_kK with the algorithmic tangent D = dS/dE.
   *
   * State: @ref MaterialState::plastic_strain is the plastic Green-Lagrange strain E_p,
   * @ref MaterialState::back_stress lives in the reference configuration (2nd Piola-Kirchhoff
   * space), @ref MaterialState::stress is the Cauchy stress.
   */
  class TotalLagrangianModel : public ConstitutiveModel
  {
  public:
    /** Model owning the stress return @p plasticity. */
    explicit TotalLagrangianModel(std::unique_ptr<PlasticityModel> plasticity);

    void evaluate(const dealii::Tensor<2, 3> &F,
                  const MaterialState        &old,
                  MaterialState              &state,
                  dealii::Tensor<2, 3>       &P,
                  dealii::Tensor<4, 3>       *tangent) const override;

    bool is_small_strain() const override { return false; }

    /** Yield function of the 2nd Piola-Kirchhoff stress S = J F^-1 sigma F^-T. */
    double yield_function(const MaterialState &state) const override;

    /** Projection of the 2nd Piola-Kirchhoff stress. */
    void make_admissible(MaterialState &state) const override;

    /** Keep the stress: E_p = E(F) - C^-1 : S with S = J F^-1 sigma F^-T. */
    void rebase(MaterialState &state, const dealii::Tensor<2, 3> &F) const override;

    const PlasticityModel &plasticity() const override { return *stress_return; }

  private:
    std::unique_ptr<PlasticityModel> stress_return; ///< return mapping in (S, E) space
  };
} // namespace ausroll::material
