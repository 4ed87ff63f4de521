#include <ausroll/core/exceptions.h>
#include <ausroll/material/plasticity_model.h>
#include <ausroll/material/tensor_functions.h>

#include <cmath>
#include <sstream>

namespace ausroll::material
{
  using dealii::SymmetricTensor;

  PlasticityModel::PlasticityModel(const MaterialParameters &parameters)
      : elastic(parameters.youngs_modulus, parameters.poissons_ratio)
      , stiffness(elastic.stiffness())
  {
  }

  ReturnMappingResult NoPlasticity::return_map(const SymmetricTensor<2, 3> &trial_stress,
                                               const SymmetricTensor<2, 3> &back_stress_old,
                                               const double) const
  {
    ReturnMappingResult result;
    result.stress = trial_stress;
    result.back_stress = back_stress_old;
    result.tangent = stiffness;
    return result;
  }

  SymmetricTensor<4, 3> NoPlasticity::back_stress_sensitivity(const ReturnMappingResult &) const
  {
    return SymmetricTensor<4, 3>(); // the elastic return does not see the back stress
  }

  SymmetricTensor<4, 3>
  VonMisesPlasticity::back_stress_sensitivity(const ReturnMappingResult &result) const
  {
    return (stiffness - result.tangent) / (2. * elastic.shear_modulus);
  }

  VonMisesPlasticity::VonMisesPlasticity(const MaterialParameters &parameters)
      : PlasticityModel(parameters)
      , hardening(parameters)
      , kinematic_modulus(parameters.kinematic_hardening_modulus)
  {
  }

  double VonMisesPlasticity::yield_function(const SymmetricTensor<2, 3> &stress,
                                            const SymmetricTensor<2, 3> &back_stress,
                                            const double                 alpha) const
  {
    const SymmetricTensor<2, 3> eta = dealii::deviator(stress) - back_stress;
    return std::sqrt(1.5 * (eta * eta)) - hardening.yield_stress(alpha);
  }

  SymmetricTensor<2, 3>
  VonMisesPlasticity::project_onto_yield_surface(const SymmetricTensor<2, 3> &stress,
                                                 const SymmetricTensor<2, 3> &back_stress,
                                                 const double                 alpha) const
  {
    const SymmetricTensor<2, 3> eta = dealii::deviator(stress) - back_stress;
    const double                q = std::sqrt(1.5 * (eta * eta));
    const double                sy = hardening.yield_stress(alpha);
    if (q <= sy)
      return stress;
    return stress - (1. - sy / q) * eta;
  }

  ReturnMappingResult VonMisesPlasticity::return_map(const SymmetricTensor<2, 3> &trial_stress,
                                                     const SymmetricTensor<2, 3> &back_stress_old,
                                                     const double                 alpha_old) const
  {
    ReturnMappingResult result;
    const double        mu = elastic.shear_modulus;

    const SymmetricTensor<2, 3> eta_trial = dealii::deviator(trial_stress) - back_stress_old;
    const double                norm_eta = std::sqrt(eta_trial * eta_trial);
    const double                q_trial = std::sqrt(1.5) * norm_eta;
    const double                sigma_y0 = hardening.yield_stress(alpha_old);

    // Elastic step. A trial state ON the yield surface (within round-off; this is where every point
    // that yielded in the last step starts the next one) gets no correction, but the continuum
    // elastic-plastic tangent: the one-sided derivative for continued loading. This makes the first
    // Newton iteration of a step as good as the following ones.
    const double f_trial = q_trial - sigma_y0;
    if (f_trial <= 1e-10 * sigma_y0)
    {
      result.stress = trial_stress;
      result.back_stress = back_stress_old;
      result.tangent = stiffness;
      if (f_trial > -1e-10 * sigma_y0 && norm_eta > 0.)
      {
        const SymmetricTensor<2, 3> N = eta_trial / norm_eta;
        add_outer_product(result.tangent,
                          -6. * mu * mu
                              / (3. * mu + kinematic_modulus + hardening.slope(alpha_old)),
                          N,
                          N);
      }
      return result;
    }

    // Scalar consistency condition g(dgamma) = q_trial - (3 mu + H_k) dgamma -
    // sigma_y(alpha+dgamma).
    const double three_mu_hk = 3. * mu + kinematic_modulus;
    double       dgamma = (q_trial - sigma_y0) / (three_mu_hk + hardening.slope(alpha_old));
    double       h_total = 0.;
    for (unsigned int it = 0;; ++it)
    {
      const double g = q_trial - three_mu_hk * dgamma - hardening.yield_stress(alpha_old + dgamma);
      h_total = three_mu_hk + hardening.slope(alpha_old + dgamma);
      const double ddg = g / h_total;
      dgamma += ddg;
      if (dgamma < 0.)
        dgamma = 0.5 * (dgamma - ddg);
      if (std::abs(ddg) <= 1e-14 * (dgamma + 1e-300) || std::abs(g) <= 1e-13 * sigma_y0)
        break;
      if (it == 50)
      {
        std::ostringstream msg;
        msg << "von Mises return mapping did not converge (q_trial = " << q_trial
            << ", sigma_y = " << sigma_y0 << ")";
        throw RunFailure(msg.str());
      }
    }
    h_total = three_mu_hk + hardening.slope(alpha_old + dgamma);

    const SymmetricTensor<2, 3> N = eta_trial / norm_eta; // unit flow direction
    result.plastic = true;
    result.eq_plastic_strain_increment = dgamma;
    result.plastic_strain_increment = std::sqrt(1.5) * dgamma * N;
    result.stress = trial_stress - 2. * mu * result.plastic_strain_increment;
    result.back_stress
        = back_stress_old + (2. / 3.) * kinematic_modulus * result.plastic_strain_increment;

    const double ratio = dgamma / q_trial;
    result.tangent = stiffness - 6. * mu * mu * ratio * dealii::deviator_tensor<3>();
    add_outer_product(result.tangent, 6. * mu * mu * (ratio - 1. / h_total), N, N);
    return result;
  }

  std::unique_ptr<PlasticityModel> create_plasticity_model(const MaterialParameters &parameters)
  {
    if (parameters.yield_criterion == YieldCriterion::none)
      return std::make_unique<NoPlasticity>(parameters);
    return std::make_unique<VonMisesPlasticity>(parameters);
  }
} // namespace ausroll::material
