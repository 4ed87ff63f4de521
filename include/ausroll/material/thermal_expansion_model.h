/**
 * @file thermal_expansion_model.h
 * Thermal strain around any constitutive model, and the plastic work that heats the workpiece.
 */
#pragma once

#include <ausroll/material/property_table.h>
#include <ausroll/material/wrapped_model.h>

#include <memory>

namespace ausroll::material
{
  /** Thermal expansion of a thermal scene (`Thermal` subsection). */
  struct ThermalExpansionParameters
  {
    PropertyTable expansion;                   ///< `Thermal/Thermal expansion` alpha(T) (1/K)
    double        reference_temperature = 20.; ///< `Thermal/Reference temperature` (stress-free)
  };

  /**
   * Wraps a ConstitutiveModel (any kinematics) with isotropic thermal expansion at the temperature
   * of the state (`Thermal/Thermal expansion` alpha(T), secant from `Thermal/Reference
   * temperature` T_ref, at which the material is stress-free). The temperature is read from the
   * committed state (@p old.temperature), which the thermal field writes after each step: the
   * mechanical step is solved at the temperature of its start (isothermal split).
   *
   * With the thermal stretch theta = 1 + alpha(T) (T - T_ref):
   * - small strain: additive, eps_mech = eps - (theta - 1) I: the inner model sees
   *   F_mech = F - (theta - 1) I; P and dP/dF are the inner model's;
   * - total Lagrangian, updated Lagrangian, finite strain: multiplicative, F = F_e F_theta F_p with
   *   F_theta = theta I (isotropic, so it commutes with F_p): the inner model sees F_mech = F /
   * theta (per unit volume of the thermally expanded intermediate configuration); per unit
   * reference volume P = theta^2 P_mech(F / theta) and dP/dF = theta dP_mech/dF_mech. The Cauchy
   * stress is the inner model's.
   *
   * Plastic work: state.plastic_work = old.plastic_work + J (sigma_vm,n + sigma_vm,n+1) / 2 *
   * (alpha_n+1 - alpha_n), the trapezoidal rule of int tau_vm d alpha with J = det F at the end
   * of the step (exact for linear isotropic hardening in small strain; plastic flow is isochoric,
   * so J differs from 1 only elastically and thermally). It is the plastic work of the von Mises
   * stress; with kinematic hardening it includes the stored part, which the Taylor-Quinney factor
   * of the heat source accounts for.
   */
  class ThermalExpansionModel : public WrappedModel
  {
  public:
    ThermalExpansionModel(std::unique_ptr<ConstitutiveModel> inner,
                          const PropertyTable               &expansion,
                          const double                       reference_temperature);

    void evaluate(const dealii::Tensor<2, 3> &F,
                  const MaterialState        &old,
                  MaterialState              &state,
                  dealii::Tensor<2, 3>       &P,
                  dealii::Tensor<4, 3>       *tangent) const override;

    void rebase(MaterialState &state, const dealii::Tensor<2, 3> &F) const override;

    /** theta(T) = 1 + alpha(T) (T - T_ref). */
    double thermal_stretch(const double temperature) const;

  private:
    PropertyTable expansion;             ///< alpha(T), secant (1/K)
    double        reference_temperature; ///< stress-free temperature
  };
} // namespace ausroll::material
