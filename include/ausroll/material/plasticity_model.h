/**
 * @file plasticity_model.h
 * Stress return (return mapping) of rate-independent plasticity in a small-strain format:
 * given an elastic trial stress, find the admissible stress and the algorithmic tangent.
 * All kinematic variants (small strain, total Lagrangian, updated Lagrangian, finite strain with
 * logarithmic elastic strain) reuse the same return mapping.
 */
#pragma once

#include <ausroll/material/elasticity.h>
#include <ausroll/material/hardening_law.h>
#include <ausroll/material/material_parameters.h>
#include <ausroll/material/transformation_plasticity.h>

#include <deal.II/base/symmetric_tensor.h>

#include <memory>
#include <optional>

namespace ausroll::material
{
  /**
   * Result of one return mapping.
   */
  struct ReturnMappingResult
  {
    dealii::SymmetricTensor<2, 3> stress;                           ///< admissible stress
    dealii::SymmetricTensor<2, 3> plastic_strain_increment;         ///< Delta eps_p
    dealii::SymmetricTensor<2, 3> back_stress;                      ///< updated back stress
    double                        eq_plastic_strain_increment = 0.; ///< Delta alpha
    dealii::SymmetricTensor<4, 3>
         tangent;         ///< algorithmic tangent d stress / d (elastic trial strain)
    bool plastic = false; ///< true if the step was plastic
    /** True if a TRIP strain is part of plastic_strain_increment (phases with `TRIP
        coefficient`; then it is nonzero even in an elastic step). */
    bool trip = false;
    /** c = 1 + 2 mu kappa of the TRIP return (dev sigma = (dev sigma_trial - 2 mu Delta eps_p) /
        c); 1 without TRIP. */
    double trip_factor = 1.;
  };

  /**
   * Elastic-plastic stress update in stress space. The trial stress is sigma_trial = C :
   * eps_e_trial; the result's tangent is d sigma / d eps_e_trial (consistent with the discrete
   * update).
   *
   * Every call takes the temperature of the material point (an external state variable, as in
   * MFront's behaviours): the moduli and hardening parameters are PropertyTable values of
   * `Material`, evaluated at that temperature (isothermal scenes: constants, the temperature is
   * not read). The kinematics pass MaterialState::temperature of the committed state, the
   * temperature field at the start of the step (the isothermal split holds it fixed during the
   * mechanical solve, so the tangent has no temperature term).
   *
   * The seam for a yield criterion (`Material/Yield criterion`): a new criterion derives from this
   * class and provides
   *  - return_map(): admissible stress, plastic strain increment, updated back stress, Delta alpha
   *    and the consistent tangent d sigma / d eps_e_trial;
   *  - yield_function() (negative inside the elastic domain; used for `yield_excess` and checks);
   *  - project_onto_yield_surface() (after a mesh transfer; the default does not project, which
   *    is right only for an elastic model);
   *  - back_stress_sensitivity(): d sigma / d back_stress_old, which the finite-strain models need
   *    because they rotate the back stress before the return. It is pure virtual: the J2 shortcut
   *    (C - D) / (2 mu) holds only for returns that see the trial state through
   *    dev(sigma_trial) - back_stress_old with a deviatoric correction, so every criterion states
   *    its own (e.g. by differentiating its return map with respect to the back stress).
   * The kinematics (SmallStrainModel, TotalLagrangianModel, UpdatedLagrangianJaumannModel,
   * FiniteStrainLogModel) and the PlaneStressDriver use nothing else, and
   * create_plasticity_model() is the one factory line to add.
   *
   * Phases (TRIP and the mixture rule of the yield stress, TransformationPlasticity): the
   * kinematics call the overloads with a PhaseStep; without the `Phases` entries that switch
   * them on they forward to the calls above (the same stress bit for bit), with them they call
   * transforming_return_map() and its siblings, which a criterion overrides to support phases
   * (von Mises and none do; the default throws).
   */
  class PlasticityModel
  {
  public:
    /** Model with the elastic moduli of @p parameters. */
    explicit PlasticityModel(const MaterialParameters &parameters);
    virtual ~PlasticityModel() = default;

    /**
     * Return @p trial_stress to the yield surface given the state at the start of the step
     * (back stress @p back_stress_old, equivalent plastic strain @p alpha_old) at
     * @p temperature.
     */
    virtual ReturnMappingResult return_map(const dealii::SymmetricTensor<2, 3> &trial_stress,
                                           const dealii::SymmetricTensor<2, 3> &back_stress_old,
                                           const double                         alpha_old,
                                           const double temperature) const = 0;

    /**
     * The stress on the yield surface closest to @p stress in the deviatoric sense, or @p stress
     * itself if it is admissible. Used after a mesh transfer (polynomial interpolation may leave
     * a state slightly outside). Default: no projection (elastic).
     */
    virtual dealii::SymmetricTensor<2, 3>
    project_onto_yield_surface(const dealii::SymmetricTensor<2, 3> &stress,
                               const dealii::SymmetricTensor<2, 3> &back_stress,
                               const double                         alpha,
                               const double                         temperature) const
    {
      (void)back_stress;
      (void)alpha;
      (void)temperature;
      return stress;
    }

    /** Value of the yield function at @p temperature (negative inside the elastic domain). */
    virtual double yield_function(const dealii::SymmetricTensor<2, 3> &stress,
                                  const dealii::SymmetricTensor<2, 3> &back_stress,
                                  const double                         alpha,
                                  const double                         temperature) const = 0;

    /**
     * Sensitivity of the returned stress to the back stress at the start of the step,
     * d stress / d back_stress_old (for a deviatoric perturbation of the back stress), at the
     * return @p result of return_map(). The finite-strain models need it because they rotate the
     * back stress with the deformation before the return; only their tangent uses it.
     */
    virtual dealii::SymmetricTensor<4, 3>
    back_stress_sensitivity(const ReturnMappingResult &result, const double temperature) const = 0;

    /** return_map() over a step with the phase fractions @p phases (TRIP, mixture rule). */
    ReturnMappingResult return_map(const dealii::SymmetricTensor<2, 3> &trial_stress,
                                   const dealii::SymmetricTensor<2, 3> &back_stress_old,
                                   const double                         alpha_old,
                                   const double                         temperature,
                                   const PhaseStep                     &phases) const
    {
      if (!transformation)
        return return_map(trial_stress, back_stress_old, alpha_old, temperature);
      return transforming_return_map(trial_stress, back_stress_old, alpha_old, temperature, phases);
    }

    /** yield_function() at the phase fractions of @p phases (the mixture rule). */
    double yield_function(const dealii::SymmetricTensor<2, 3> &stress,
                          const dealii::SymmetricTensor<2, 3> &back_stress,
                          const double                         alpha,
                          const double                         temperature,
                          const PhaseStep                     &phases) const
    {
      if (!transformation)
        return yield_function(stress, back_stress, alpha, temperature);
      return transforming_yield_function(stress, back_stress, alpha, temperature, phases);
    }

    /** project_onto_yield_surface() at the phase fractions of @p phases (the mixture rule). */
    dealii::SymmetricTensor<2, 3>
    project_onto_yield_surface(const dealii::SymmetricTensor<2, 3> &stress,
                               const dealii::SymmetricTensor<2, 3> &back_stress,
                               const double                         alpha,
                               const double                         temperature,
                               const PhaseStep                     &phases) const
    {
      if (!transformation)
        return project_onto_yield_surface(stress, back_stress, alpha, temperature);
      return transforming_projection(stress, back_stress, alpha, temperature, phases);
    }

    /** Switch on TRIP and the mixture rule of @p parameters (nothing if they are off). */
    void set_transformation(const TransformationPlasticityParameters &parameters)
    {
      if (parameters.active())
        transformation = std::make_shared<const TransformationPlasticity>(parameters);
    }

    /** The elastic law at @p temperature. */
    IsotropicElasticity elasticity(const double temperature) const
    {
      if (!elastic_depends_on_temperature)
        return elastic;
      return IsotropicElasticity(youngs_modulus.value(temperature),
                                 poissons_ratio.value(temperature));
    }

  protected:
    /**
     * The return with TRIP and the mixture rule (only called when set_transformation() switched
     * them on): as return_map(), with Delta eps_tp = kappa dev(sigma) added to the plastic strain
     * increment and the yield stress of the mixture at the end of the step. Default: throws
     * (a criterion without phase support).
     */
    virtual ReturnMappingResult
    transforming_return_map(const dealii::SymmetricTensor<2, 3> &trial_stress,
                            const dealii::SymmetricTensor<2, 3> &back_stress_old,
                            const double                         alpha_old,
                            const double                         temperature,
                            const PhaseStep                     &phases) const;

    /** yield_function() with the mixture rule. Default: throws. */
    virtual double transforming_yield_function(const dealii::SymmetricTensor<2, 3> &stress,
                                               const dealii::SymmetricTensor<2, 3> &back_stress,
                                               const double                         alpha,
                                               const double                         temperature,
                                               const PhaseStep                     &phases) const;

    /** project_onto_yield_surface() with the mixture rule. Default: no projection. */
    virtual dealii::SymmetricTensor<2, 3>
    transforming_projection(const dealii::SymmetricTensor<2, 3> &stress,
                            const dealii::SymmetricTensor<2, 3> &back_stress,
                            const double                         alpha,
                            const double                         temperature,
                            const PhaseStep                     &phases) const;

    /** TRIP and the mixture rule (null: off, the calls without phases run). */
    std::shared_ptr<const TransformationPlasticity> transformation;

    /** The elasticity tensor C at @p temperature: the stored one for constant moduli (no copy
        on the material point's path), else computed into @p storage. */
    const dealii::SymmetricTensor<4, 3> &
    stiffness_at(const double                                  temperature,
                 std::optional<dealii::SymmetricTensor<4, 3>> &storage) const
    {
      if (!elastic_depends_on_temperature)
        return stiffness;
      return storage.emplace(elasticity(temperature).stiffness());
    }

    PropertyTable                 youngs_modulus;                 ///< E(T)
    PropertyTable                 poissons_ratio;                 ///< nu(T)
    bool                          elastic_depends_on_temperature; ///< E or nu is a table
    IsotropicElasticity           elastic;   ///< elastic moduli (constant moduli)
    dealii::SymmetricTensor<4, 3> stiffness; ///< C (constant moduli)
  };

  /**
   * `Yield criterion = none`: purely elastic.
   */
  class NoPlasticity : public PlasticityModel
  {
  public:
    using PlasticityModel::PlasticityModel;
    using PlasticityModel::project_onto_yield_surface;
    using PlasticityModel::return_map;
    using PlasticityModel::yield_function;

    ReturnMappingResult return_map(const dealii::SymmetricTensor<2, 3> &trial_stress,
                                   const dealii::SymmetricTensor<2, 3> &back_stress_old,
                                   const double                         alpha_old,
                                   const double                         temperature) const override;

    double yield_function(const dealii::SymmetricTensor<2, 3> &,
                          const dealii::SymmetricTensor<2, 3> &,
                          const double,
                          const double) const override
    {
      return -1.;
    }

    /** Zero: the elastic return does not see the back stress. */
    dealii::SymmetricTensor<4, 3> back_stress_sensitivity(const ReturnMappingResult &result,
                                                          const double temperature) const override;

  protected:
    /** Elastic with TRIP: dev sigma = dev sigma_trial / (1 + 2 mu kappa). */
    ReturnMappingResult
    transforming_return_map(const dealii::SymmetricTensor<2, 3> &trial_stress,
                            const dealii::SymmetricTensor<2, 3> &back_stress_old,
                            const double                         alpha_old,
                            const double                         temperature,
                            const PhaseStep                     &phases) const override;

    /** -1: never yields. */
    double transforming_yield_function(const dealii::SymmetricTensor<2, 3> &,
                                       const dealii::SymmetricTensor<2, 3> &,
                                       const double,
                                       const double,
                                       const PhaseStep &) const override
    {
      return -1.;
    }
  };

  /**
   * `Yield criterion = von Mises`: f = sqrt(3/2) |dev sigma - beta| - sigma_y(alpha) with isotropic
   * hardening (linear or power law) and linear Prager kinematic hardening
   * beta' = 2/3 H_k eps_p'. Radial return (one scalar Newton iteration loop for nonlinear
   * hardening) and the consistent algorithmic tangent D = C - 6 mu^2 dgamma/q I_dev + 6 mu^2
   * (dgamma/q - 1/(3 mu + H_k + H')) N (x) N.
   */
  class VonMisesPlasticity : public PlasticityModel
  {
  public:
    /** Model from subsection `Material`. */
    explicit VonMisesPlasticity(const MaterialParameters &parameters);
    using PlasticityModel::project_onto_yield_surface;
    using PlasticityModel::return_map;
    using PlasticityModel::yield_function;

    ReturnMappingResult return_map(const dealii::SymmetricTensor<2, 3> &trial_stress,
                                   const dealii::SymmetricTensor<2, 3> &back_stress_old,
                                   const double                         alpha_old,
                                   const double                         temperature) const override;

    double yield_function(const dealii::SymmetricTensor<2, 3> &stress,
                          const dealii::SymmetricTensor<2, 3> &back_stress,
                          const double                         alpha,
                          const double                         temperature) const override;

    /** Radial scaling of dev(sigma) - beta onto the yield surface; pressure unchanged. */
    dealii::SymmetricTensor<2, 3>
    project_onto_yield_surface(const dealii::SymmetricTensor<2, 3> &stress,
                               const dealii::SymmetricTensor<2, 3> &back_stress,
                               const double                         alpha,
                               const double                         temperature) const override;

    /**
     * (C - D) / (2 mu) from the algorithmic tangent D of @p result: the radial return depends on
     * the trial state only through eta = dev(sigma_trial) - beta_old and its correction is
     * deviatoric, so a deviatoric change of beta_old acts as minus the same change of
     * dev(sigma_trial) = 2 mu dev(eps_e_trial).
     */
    dealii::SymmetricTensor<4, 3> back_stress_sensitivity(const ReturnMappingResult &result,
                                                          const double temperature) const override;

  protected:
    /**
     * Radial return with TRIP and the mixture rule. With c = 1 + 2 mu kappa the equations
     * dev sigma = (dev sigma_trial - 2 mu Delta eps_p) / c, beta = beta_old + 2/3 H_k Delta
     * eps_p and Delta eps_p along dev sigma - beta reduce to one scalar consistency condition in
     * eta* = dev sigma_trial / c - beta_old: sqrt(3/2) |eta*| - (3 mu / c + H_k) dgamma -
     * sigma_y,mix(alpha + dgamma) = 0 (doc/theory.md, "TRIP and the mixture rule").
     */
    ReturnMappingResult
    transforming_return_map(const dealii::SymmetricTensor<2, 3> &trial_stress,
                            const dealii::SymmetricTensor<2, 3> &back_stress_old,
                            const double                         alpha_old,
                            const double                         temperature,
                            const PhaseStep                     &phases) const override;

    /** sqrt(3/2) |dev sigma - beta| - sigma_y,mix(alpha). */
    double transforming_yield_function(const dealii::SymmetricTensor<2, 3> &stress,
                                       const dealii::SymmetricTensor<2, 3> &back_stress,
                                       const double                         alpha,
                                       const double                         temperature,
                                       const PhaseStep                     &phases) const override;

    /** Radial scaling onto the yield surface of the mixture. */
    dealii::SymmetricTensor<2, 3>
    transforming_projection(const dealii::SymmetricTensor<2, 3> &stress,
                            const dealii::SymmetricTensor<2, 3> &back_stress,
                            const double                         alpha,
                            const double                         temperature,
                            const PhaseStep                     &phases) const override;

  private:
    /** The isotropic hardening law at @p temperature. */
    HardeningLaw hardening_at(const double temperature) const
    {
      return hardening_depends_on_temperature ? HardeningLaw(parameters, temperature) : hardening;
    }

    MaterialParameters parameters;                 ///< the tables of `Material`
    bool         hardening_depends_on_temperature; ///< a hardening parameter or H_k is a table
    HardeningLaw hardening;         ///< isotropic hardening sigma_y(alpha) (constant case)
    double       kinematic_modulus; ///< H_k (constant case)
  };

  /** The plasticity model selected by `Material/Yield criterion`, with TRIP and the mixture rule
      of @p transformation (the `Phases` entries) if given and on. */
  std::unique_ptr<PlasticityModel>
  create_plasticity_model(const MaterialParameters                 &parameters,
                          const TransformationPlasticityParameters *transformation = nullptr);
} // namespace ausroll::material
