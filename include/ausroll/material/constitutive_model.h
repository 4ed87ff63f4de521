/**
 * @file constitutive_model.h
 * Constitutive models in deformation-gradient form: F -> (P, dP/dF). One interface serves small
 * strain, total Lagrangian, updated Lagrangian (Jaumann) and finite-strain (logarithmic) models,
 * so the assembler is the same for all of them.
 */
#pragma once

#include <ausroll/material/material_state.h>
#include <ausroll/material/plasticity_model.h>

#include <deal.II/base/tensor.h>

#include <memory>
#include <string>

namespace ausroll::material
{
  /** Kinematic description of a scene (`Model/Kinematics`). */
  enum class KinematicsType
  {
    small_strain,       ///< infinitesimal strain, reference configuration
    total_lagrangian,   ///< Green-Lagrange strain, 2nd Piola-Kirchhoff stress
    updated_lagrangian, ///< hypoelastic-plastic, Jaumann rate (as NOFEAP)
    finite_strain       ///< multiplicative J2 with logarithmic (Hencky) elastic strain
  };

  struct ThermalExpansionParameters;
  struct PhaseParameters;

  /** Parse a `Model/Kinematics` value. */
  KinematicsType parse_kinematics(const std::string &name);

  /** The `Model/Kinematics` name of @p type. */
  std::string to_string(const KinematicsType type);

  /**
   * A constitutive model evaluated at one material point. The input is the 3x3 deformation gradient
   * F (2D models embed their in-plane gradient, see mechanics::PlanarKinematics); the outputs are
   * the first Piola-Kirchhoff stress P and, if requested, the consistent tangent A = dP/dF
   * (A[i][J][k][L] = dP_iJ / dF_kL). The model reads the committed state @p old and writes the
   * trial state @p state, which includes the Cauchy stress.
   */
  class ConstitutiveModel
  {
  public:
    virtual ~ConstitutiveModel() = default;

    /** Evaluate stress (and tangent if @p tangent is not null) at deformation gradient @p F. */
    virtual void evaluate(const dealii::Tensor<2, 3> &F,
                          const MaterialState        &old,
                          MaterialState              &state,
                          dealii::Tensor<2, 3>       &P,
                          dealii::Tensor<4, 3>       *tangent) const = 0;

    /**
     * The length of the load step (time in s) that the following evaluations belong to, for laws
     * with kinetics (PhaseTransformationModel's bainite); 0 outside a step (re-equilibration after
     * a mesh change, output). Set by the scene, single-threaded, before the step's assemblies;
     * ASPECT's material models read the time step the same way. Default: not used.
     */
    virtual void set_step_length(const double dt) { (void)dt; }

    /** True if the model neglects geometric nonlinearity (the mesh never moves). */
    virtual bool is_small_strain() const = 0;

    /** The elastic-plastic stress return used by the model. */
    virtual const PlasticityModel &plasticity() const = 0;

    /**
     * After the state was moved to a new mesh (MaterialPointTransfer): make @p state consistent
     * with the deformation gradient @p F of the interpolated displacement while keeping its
     * stress and hardening variables, so that the next evaluation at @p F returns the transferred
     * stress. Default (models integrating from the last deformation gradient): F_n = F.
     */
    virtual void rebase(MaterialState &state, const dealii::Tensor<2, 3> &F) const
    {
      state.deformation_gradient = F;
    }

    /**
     * Yield function of @p state in the stress measure the model returns in (Cauchy for small
     * strain and updated Lagrangian). Positive values are violations; used to check that mesh
     * transfer creates none.
     */
    virtual double yield_function(const MaterialState &state) const
    {
      return plasticity().yield_function(state.stress,
                                         state.back_stress,
                                         state.equivalent_plastic_strain,
                                         state.temperature,
                                         PhaseStep::at(state));
    }

    /** Project the stress of @p state onto the yield surface if it lies outside (after a mesh
        transfer); in the stress measure of yield_function(). */
    virtual void make_admissible(MaterialState &state) const
    {
      state.stress = plasticity().project_onto_yield_surface(state.stress,
                                                             state.back_stress,
                                                             state.equivalent_plastic_strain,
                                                             state.temperature,
                                                             PhaseStep::at(state));
    }
  };

  /**
   * Build the model for `Model/Kinematics` = @p kinematics with the plasticity of subsection
   * `Material`. With @p thermal (thermal scenes) the model is wrapped in a ThermalExpansionModel,
   * with @p phases (`Phases/Enabled`) that in a PhaseTransformationModel;
   * with @p plane_stress the result is wrapped in a PlaneStressDriver.
   */
  std::unique_ptr<ConstitutiveModel>
  create_constitutive_model(const KinematicsType              kinematics,
                            const MaterialParameters         &material,
                            const bool                        plane_stress,
                            const ThermalExpansionParameters *thermal = nullptr,
                            const PhaseParameters            *phases = nullptr);
} // namespace ausroll::material
