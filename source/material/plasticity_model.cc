#include <ausroll/core/exceptions.h>
#include <ausroll/material/plasticity_model.h>
#include <ausroll/material/tensor_functions.h>

#include <cmath>
#include <sstream>

namespace ausroll::material
{
  using dealii::SymmetricTensor;

  PlasticityModel::PlasticityModel(const MaterialParameters &parameters)
      : youngs_modulus(parameters.youngs_modulus)
      , poissons_ratio(parameters.poissons_ratio)
      , elastic_depends_on_temperature(!youngs_modulus.is_constant()
                                       || !poissons_ratio.is_constant())
      , elastic(youngs_modulus.value(0.), poissons_ratio.value(0.))
      , stiffness(elastic.stiffness())
  {
  }

  ReturnMappingResult NoPlasticity::return_map(const SymmetricTensor<2, 3> &trial_stress,
                                               const SymmetricTensor<2, 3> &back_stress_old,
                                               const double,
                                               const double temperature) const
  {
    ReturnMappingResult result;
    result.stress = trial_stress;
    result.back_stress = back_stress_old;
    std::optional<SymmetricTensor<4, 3>> storage;
    result.tangent = stiffness_at(temperature, storage);
    return result;
  }

  SymmetricTensor<4, 3> NoPlasticity::back_stress_sensitivity(const ReturnMappingResult &,
                                                              const double) const
  {
    return SymmetricTensor<4, 3>(); // the elastic return does not see the back stress
  }

  SymmetricTensor<4, 3>
  VonMisesPlasticity::back_stress_sensitivity(const ReturnMappingResult &result,
                                              const double               temperature) const
  {
    std::optional<SymmetricTensor<4, 3>> storage;
    return (stiffness_at(temperature, storage) - result.tangent)
           / (2. * elasticity(temperature).shear_modulus);
  }

  VonMisesPlasticity::VonMisesPlasticity(const MaterialParameters &parameters_in)
      : PlasticityModel(parameters_in)
      , parameters(parameters_in)
      , hardening_depends_on_temperature(!parameters.yield_stress.is_constant()
                                         || !parameters.hardening_modulus.is_constant()
                                         || !parameters.reference_plastic_strain.is_constant()
                                         || !parameters.hardening_exponent.is_constant()
                                         || !parameters.kinematic_hardening_modulus.is_constant())
      , hardening(parameters, 0.)
      , kinematic_modulus(parameters.kinematic_hardening_modulus.value(0.))
  {
  }

  double VonMisesPlasticity::yield_function(const SymmetricTensor<2, 3> &stress,
                                            const SymmetricTensor<2, 3> &back_stress,
                                            const double                 alpha,
                                            const double                 temperature) const
  {
    const SymmetricTensor<2, 3> eta = dealii::deviator(stress) - back_stress;
    return std::sqrt(1.5 * (eta * eta)) - hardening_at(temperature).yield_stress(alpha);
  }

  SymmetricTensor<2, 3>
  VonMisesPlasticity::project_onto_yield_surface(const SymmetricTensor<2, 3> &stress,
                                                 const SymmetricTensor<2, 3> &back_stress,
                                                 const double                 alpha,
                                                 const double                 temperature) const
  {
    const SymmetricTensor<2, 3> eta = dealii::deviator(stress) - back_stress;
    const double                q = std::sqrt(1.5 * (eta * eta));
    const double                sy = hardening_at(temperature).yield_stress(alpha);
    if (q <= sy)
      return stress;
    return stress - (1. - sy / q) * eta;
  }

  ReturnMappingResult VonMisesPlasticity::return_map(const SymmetricTensor<2, 3> &trial_stress,
                                                     const SymmetricTensor<2, 3> &back_stress_old,
                                                     const double                 alpha_old,
                                                     const double                 temperature) const
  {
    ReturnMappingResult                  result;
    const double                         mu = elasticity(temperature).shear_modulus;
    std::optional<SymmetricTensor<4, 3>> C_storage;
    const SymmetricTensor<4, 3>         &C = stiffness_at(temperature, C_storage);
    const HardeningLaw                   law = hardening_at(temperature);
    const double                         H_k = hardening_depends_on_temperature
                                                   ? parameters.kinematic_hardening_modulus.value(temperature)
                                                   : kinematic_modulus;

    const SymmetricTensor<2, 3> eta_trial = dealii::deviator(trial_stress) - back_stress_old;
    const double                norm_eta = std::sqrt(eta_trial * eta_trial);
    const double                q_trial = std::sqrt(1.5) * norm_eta;
    const double                sigma_y0 = law.yield_stress(alpha_old);

    // Elastic step. A trial state ON the yield surface (within round-off; this is where every point
    // that yielded in the last step starts the next one) gets no correction, but the continuum
    // elastic-plastic tangent: the one-sided derivative for continued loading. This makes the first
    // Newton iteration of a step as good as the following ones.
    const double f_trial = q_trial - sigma_y0;
    if (f_trial <= 1e-10 * sigma_y0)
    {
      result.stress = trial_stress;
      result.back_stress = back_stress_old;
      result.tangent = C;
      if (f_trial > -1e-10 * sigma_y0 && norm_eta > 0.)
      {
        const SymmetricTensor<2, 3> N = eta_trial / norm_eta;
        add_outer_product(
            result.tangent, -6. * mu * mu / (3. * mu + H_k + law.slope(alpha_old)), N, N);
      }
      return result;
    }

    // Scalar consistency condition g(dgamma) = q_trial - (3 mu + H_k) dgamma -
    // sigma_y(alpha+dgamma).
    const double three_mu_hk = 3. * mu + H_k;
    double       dgamma = (q_trial - sigma_y0) / (three_mu_hk + law.slope(alpha_old));
    double       h_total = 0.;
    for (unsigned int it = 0;; ++it)
    {
      const double g = q_trial - three_mu_hk * dgamma - law.yield_stress(alpha_old + dgamma);
      h_total = three_mu_hk + law.slope(alpha_old + dgamma);
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
    h_total = three_mu_hk + law.slope(alpha_old + dgamma);

    const SymmetricTensor<2, 3> N = eta_trial / norm_eta; // unit flow direction
    result.plastic = true;
    result.eq_plastic_strain_increment = dgamma;
    result.plastic_strain_increment = std::sqrt(1.5) * dgamma * N;
    result.stress = trial_stress - 2. * mu * result.plastic_strain_increment;
    result.back_stress = back_stress_old + (2. / 3.) * H_k * result.plastic_strain_increment;

    const double ratio = dgamma / q_trial;
    result.tangent = C - 6. * mu * mu * ratio * dealii::deviator_tensor<3>();
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
