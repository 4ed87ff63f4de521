/**
 * @file finite_strain_log_model.h
 * Multiplicative finite-strain J2 plasticity with logarithmic elastic strain
 * (`Model/Kinematics = finite strain`).
 */
#pragma once

#include <ausroll/material/constitutive_model.h>

namespace ausroll::material
{
  /**
   * Simo's multiplicative J2 plasticity with Hencky (logarithmic) elasticity, exponential-map
   * return in principal-stretch-free tensor form:
   *
   * - C_p,n^-1 = F_n^-1 b_e,n F_n^-T from the committed state (F_n, b_e,n);
   * - b_e^trial = F C_p,n^-1 F^T, eps_e^trial = ln(b_e^trial) / 2, Kirchhoff stress
   *   tau^trial = C : eps_e^trial;
   * - back stress (Kirchhoff space, spatial) transported with the rotation Delta R of the polar
   *   decomposition of the increment f = F F_n^-1 = Delta R Delta U, so that a superposed rigid
   *   rotation rotates everything exactly: beta^trial = Delta R beta_n Delta R^T;
   * - the PlasticityModel's return map gives tau, Delta eps_p; eps_e = eps_e^trial - Delta eps_p,
   *   b_e = exp(2 eps_e) (exponential map: plastically volume preserving); when eps_e is diagonal
   *   in the eigenvectors of b^trial up to round-off (isotropic elasticity and a return along
   *   dev tau^trial, as von Mises without back stress), exp and b_e^-1 reuse that decomposition;
   * - sigma = tau / J, P = tau F^-T.
   *
   * The yield function is evaluated with the Kirchhoff stress tau (as usual for this model), so in
   * uniaxial tension tau = sigma_y(alpha) and the true (Cauchy) stress is sigma_y(alpha) / J_e with
   * the elastic volume ratio J_e = det F = exp((1 - 2 nu) tau / E) (a 0.1-0.2 % difference for
   * steels).
   *
   * Tangent: exact, by the chain rule. d tau = D : (d ln b / d b) : d b^trial / 2
   * (+ the back-stress rotation term), where d ln b / d b comes from the spectral decomposition
   * with divided differences (see logarithm()), d b^trial = dF C_p,n^-1 F^T + F C_p,n^-1 dF^T;
   * then dP = d tau F^-T - tau F^-T dF^T F^-T. At a planar point (plane strain, axisymmetry: F,
   * F_n and b_e,n without xz, yz entries, no back stress) the tangent splits into the in-plane
   * problem and the anti-plane shear, and only their nonzero terms are summed (the same result to
   * the bit, about a third of the operations).
   *
   * State: @ref MaterialState::elastic_left_cauchy_green is b_e, @ref MaterialState::stress the
   * Cauchy stress tau / J, @ref MaterialState::back_stress the spatial back stress (Kirchhoff
   * space), @ref MaterialState::plastic_strain the Lagrangian logarithmic plastic strain
   * ln U_p = ln(C_p) / 2 with C_p = F^T b_e^-1 F (traceless; in uniaxial tension its axial
   * component is ln of the plastic stretch). It is output only and recomputed in plastic steps.
   */
  class FiniteStrainLogModel : public ConstitutiveModel
  {
  public:
    /** Model owning the stress return @p plasticity (applied to the Kirchhoff stress). */
    explicit FiniteStrainLogModel(std::unique_ptr<PlasticityModel> plasticity);

    void evaluate(const dealii::Tensor<2, 3> &F,
                  const MaterialState        &old,
                  MaterialState              &state,
                  dealii::Tensor<2, 3>       &P,
                  dealii::Tensor<4, 3>       *tangent) const override;

    bool is_small_strain() const override { return false; }

    /** Yield function of the Kirchhoff stress tau = J sigma. */
    double yield_function(const MaterialState &state) const override;

    /** Projection of the Kirchhoff stress tau = J sigma. */
    void make_admissible(MaterialState &state) const override;

    const PlasticityModel &plasticity() const override { return *stress_return; }

  private:
    std::unique_ptr<PlasticityModel> stress_return; ///< return mapping in (tau, eps_e) space
  };
} // namespace ausroll::material
