#include <ausroll/core/exceptions.h>
#include <ausroll/material/plasticity_model.h>
#include <ausroll/material/tensor_functions.h>

#include <cmath>
#include <sstream>

namespace ausroll::material
{
  using dealii::SymmetricTensor;

  namespace
  {
    /**
     * Newton's method for the consistency condition of the radial return, g(dgamma) = q - a
     * dgamma - sigma_y(alpha_old + dgamma) = 0 (a = 3 mu + H_k; with TRIP 3 mu / c + H_k), from
     * the linear estimate, halving back into dgamma >= 0; stops when the correction is below 1e-14
     * dgamma or g below 1e-13 sigma_y0 (RunFailure after 50 iterations).
     */
    template <typename YieldStress, typename Slope>
    double solve_consistency(const double       q,
                             const double       a,
                             const double       alpha_old,
                             const double       sigma_y0,
                             const YieldStress &yield_stress,
                             const Slope       &slope)
    {
      double dgamma = (q - sigma_y0) / (a + slope(alpha_old));
      for (unsigned int it = 0;; ++it)
      {
        const double g = q - a * dgamma - yield_stress(alpha_old + dgamma);
        const double ddg = g / (a + slope(alpha_old + dgamma));
        dgamma += ddg;
        if (dgamma < 0.)
          dgamma = 0.5 * (dgamma - ddg);
        if (std::abs(ddg) <= 1e-14 * (dgamma + 1e-300) || std::abs(g) <= 1e-13 * sigma_y0)
          return dgamma;
        if (it == 50)
        {
          std::ostringstream msg;
          msg << "von Mises return mapping did not converge (q_trial = " << q
              << ", sigma_y = " << sigma_y0 << ")";
          throw RunFailure(msg.str());
        }
      }
    }

    /** The linear mixture (1 - f_M - f_B) sigma_y,A + f_M (sigma_y,M(C, T) + H_M(C, T) alpha) +
        f_B sigma_y,B(C, T) at the austenite's yield stress @p austenite and the accumulated
        @p alpha. */
    double mixture_yield_stress(const TransformationPlasticity &transformation,
                                const double                    austenite,
                                const double                    alpha,
                                const PhaseStep                &phases,
                                const double                    temperature)
    {
      const double sigma = transformation.austenite_weight(phases) * austenite
                           + transformation.product_yield_stress(phases, temperature);
      if (!transformation.products_harden())
        return sigma;
      return sigma + transformation.product_hardening(phases, temperature) * alpha;
    }
  } // namespace

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

  ReturnMappingResult PlasticityModel::transforming_return_map(const SymmetricTensor<2, 3> &,
                                                               const SymmetricTensor<2, 3> &,
                                                               const double,
                                                               const double,
                                                               const PhaseStep &) const
  {
    throw InputError("Phases/TRIP coefficient: TRIP and the mixture rule of the yield stress are "
                     "not available for this Material/Yield criterion");
  }

  double PlasticityModel::transforming_yield_function(const SymmetricTensor<2, 3> &,
                                                      const SymmetricTensor<2, 3> &,
                                                      const double,
                                                      const double,
                                                      const PhaseStep &) const
  {
    throw InputError("Phases/Martensite yield stress: the mixture rule is not available for "
                     "this Material/Yield criterion");
  }

  SymmetricTensor<2, 3>
  PlasticityModel::transforming_projection(const SymmetricTensor<2, 3> &stress,
                                           const SymmetricTensor<2, 3> &,
                                           const double,
                                           const double,
                                           const PhaseStep &) const
  {
    return stress;
  }

  ReturnMappingResult
  NoPlasticity::transforming_return_map(const SymmetricTensor<2, 3> &trial_stress,
                                        const SymmetricTensor<2, 3> &back_stress_old,
                                        const double,
                                        const double     temperature,
                                        const PhaseStep &phases) const
  {
    // dev sigma = dev sigma_trial - 2 mu kappa dev sigma
    const double                         mu = elasticity(temperature).shear_modulus;
    const double                         kappa = transformation->trip_compliance(phases);
    const double                         c = 1. + 2. * mu * kappa;
    const SymmetricTensor<2, 3>          s_trial = dealii::deviator(trial_stress);
    std::optional<SymmetricTensor<4, 3>> storage;
    ReturnMappingResult                  result;
    result.stress = (trial_stress - s_trial) + s_trial / c;
    result.plastic_strain_increment = kappa * (s_trial / c);
    result.back_stress = back_stress_old;
    result.tangent = stiffness_at(temperature, storage)
                     - 2. * mu * (1. - 1. / c) * dealii::deviator_tensor<3>();
    result.trip = kappa > 0.;
    result.trip_factor = c;
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
    if (result.trip_factor == 1.)
      return (stiffness_at(temperature, storage) - result.tangent)
             / (2. * elasticity(temperature).shear_modulus);
    // with TRIP the return sees eta* = dev sigma_trial / c - beta_old: d sigma / d beta_old =
    // c (C - D) / (2 mu) - (c - 1) I_dev (doc/theory.md, "TRIP and the mixture rule")
    const double c = result.trip_factor;
    return c * (stiffness_at(temperature, storage) - result.tangent)
               / (2. * elasticity(temperature).shear_modulus)
           - (c - 1.) * dealii::deviator_tensor<3>();
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
    const double dgamma = solve_consistency(
        q_trial,
        three_mu_hk,
        alpha_old,
        sigma_y0,
        [&](const double a) { return law.yield_stress(a); },
        [&](const double a) { return law.slope(a); });
    const double h_total = three_mu_hk + law.slope(alpha_old + dgamma);

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

  double VonMisesPlasticity::transforming_yield_function(const SymmetricTensor<2, 3> &stress,
                                                         const SymmetricTensor<2, 3> &back_stress,
                                                         const double                 alpha,
                                                         const double                 temperature,
                                                         const PhaseStep             &phases) const
  {
    const SymmetricTensor<2, 3> eta = dealii::deviator(stress) - back_stress;
    return std::sqrt(1.5 * (eta * eta))
           - mixture_yield_stress(*transformation,
                                  hardening_at(temperature).yield_stress(alpha),
                                  alpha,
                                  phases,
                                  temperature);
  }

  SymmetricTensor<2, 3>
  VonMisesPlasticity::transforming_projection(const SymmetricTensor<2, 3> &stress,
                                              const SymmetricTensor<2, 3> &back_stress,
                                              const double                 alpha,
                                              const double                 temperature,
                                              const PhaseStep             &phases) const
  {
    const SymmetricTensor<2, 3> eta = dealii::deviator(stress) - back_stress;
    const double                q = std::sqrt(1.5 * (eta * eta));
    const double                sy = mixture_yield_stress(
        *transformation, hardening_at(temperature).yield_stress(alpha), alpha, phases, temperature);
    if (q <= sy)
      return stress;
    return stress - (1. - sy / q) * eta;
  }

  ReturnMappingResult
  VonMisesPlasticity::transforming_return_map(const SymmetricTensor<2, 3> &trial_stress,
                                              const SymmetricTensor<2, 3> &back_stress_old,
                                              const double                 alpha_old,
                                              const double                 temperature,
                                              const PhaseStep             &phases) const
  {
    ReturnMappingResult                  result;
    const double                         mu = elasticity(temperature).shear_modulus;
    std::optional<SymmetricTensor<4, 3>> C_storage;
    const SymmetricTensor<4, 3>         &C = stiffness_at(temperature, C_storage);
    const HardeningLaw                   law = hardening_at(temperature);
    const double                         H_k = hardening_depends_on_temperature
                                                   ? parameters.kinematic_hardening_modulus.value(temperature)
                                                   : kinematic_modulus;
    // the mixture: sigma_y(alpha) = w sigma_y,A(alpha) + f_M (sigma_y,M + H_M alpha) + f_B
    // sigma_y,B (the products' hardening term is left out without H_M: the sums of the
    // perfectly plastic products stay as they were)
    const double w = transformation->austenite_weight(phases);
    const double product = transformation->product_yield_stress(phases, temperature);
    const bool   harden = transformation->products_harden();
    const double product_slope
        = harden ? transformation->product_hardening(phases, temperature) : 0.;
    const auto yield_stress = [&](const double a)
    {
      const double sigma = w * law.yield_stress(a) + product;
      return harden ? sigma + product_slope * a : sigma;
    };
    const auto slope = [&](const double a)
    {
      const double h = w * law.slope(a);
      return harden ? h + product_slope : h;
    };
    // TRIP: Delta eps_tp = kappa dev(sigma), so dev(sigma) (1 + 2 mu kappa) = dev(sigma_trial)
    // - 2 mu Delta eps_p
    const double kappa = transformation->trip_compliance(phases);
    const double c = 1. + 2. * mu * kappa;
    result.trip = kappa > 0.;
    result.trip_factor = c;

    const SymmetricTensor<2, 3> s_trial = dealii::deviator(trial_stress);
    const SymmetricTensor<2, 3> volumetric = trial_stress - s_trial;
    const SymmetricTensor<2, 3> eta = s_trial / c - back_stress_old; // eta*
    const double                norm_eta = std::sqrt(eta * eta);
    const double                q = std::sqrt(1.5) * norm_eta;
    const double                sigma_y0 = yield_stress(alpha_old);
    const double                mu_c = mu / c;
    const SymmetricTensor<4, 3> elastic_trip
        = C - 2. * mu * (1. - 1. / c) * dealii::deviator_tensor<3>();

    // elastic step (TRIP only); on the yield surface the continuum tangent, as return_map()
    const double f_trial = q - sigma_y0;
    if (f_trial <= 1e-10 * sigma_y0)
    {
      const SymmetricTensor<2, 3> s = s_trial / c;
      result.stress = volumetric + s;
      result.plastic_strain_increment = kappa * s;
      result.back_stress = back_stress_old;
      result.tangent = elastic_trip;
      if (f_trial > -1e-10 * sigma_y0 && norm_eta > 0.)
      {
        const SymmetricTensor<2, 3> N = eta / norm_eta;
        add_outer_product(
            result.tangent, -6. * mu_c * mu_c / (3. * mu_c + H_k + slope(alpha_old)), N, N);
      }
      return result;
    }

    // scalar consistency condition g(dgamma) = q* - (3 mu / c + H_k) dgamma - sigma_y(alpha +
    // dgamma)
    const double three_mu_hk = 3. * mu_c + H_k;
    const double dgamma
        = solve_consistency(q, three_mu_hk, alpha_old, sigma_y0, yield_stress, slope);
    const double h_total = three_mu_hk + slope(alpha_old + dgamma);

    const SymmetricTensor<2, 3> N = eta / norm_eta; // the flow direction of eta*
    const SymmetricTensor<2, 3> d_plastic = std::sqrt(1.5) * dgamma * N;
    const SymmetricTensor<2, 3> s = (s_trial - 2. * mu * d_plastic) / c;
    result.plastic = true;
    result.eq_plastic_strain_increment = dgamma;
    result.stress = volumetric + s;
    result.plastic_strain_increment = d_plastic + kappa * s;
    result.back_stress = back_stress_old + (2. / 3.) * H_k * d_plastic;

    // D = C - 2 mu (1 - 1/c) I_dev - 6 (mu/c)^2 dgamma/q* I_dev + 6 (mu/c)^2 (dgamma/q* - 1/h) N N
    const double ratio = dgamma / q;
    result.tangent = elastic_trip - 6. * mu_c * mu_c * ratio * dealii::deviator_tensor<3>();
    add_outer_product(result.tangent, 6. * mu_c * mu_c * (ratio - 1. / h_total), N, N);
    return result;
  }

  std::unique_ptr<PlasticityModel>
  create_plasticity_model(const MaterialParameters                 &parameters,
                          const TransformationPlasticityParameters *transformation)
  {
    std::unique_ptr<PlasticityModel> model;
    if (parameters.yield_criterion == YieldCriterion::none)
      model = std::make_unique<NoPlasticity>(parameters);
    else
      model = std::make_unique<VonMisesPlasticity>(parameters);
    if (transformation != nullptr)
      model->set_transformation(*transformation);
    return model;
  }
} // namespace ausroll::material
