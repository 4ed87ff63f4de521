/**
 * @file material_state.h
 * The state carried by one material (quadrature) point.
 */
#pragma once

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <vector>

namespace ausroll::material
{
  /**
   * State variables of a material point in 3D. Every constitutive model uses the same record, so
   * that transfer across mesh refinement and checkpointing treat all models alike.
   *
   * - @ref stress: Cauchy stress sigma (all models keep it current, for output and for the
   *   rate form of the updated Lagrangian model).
   * - @ref plastic_strain: plastic strain of the model (small strain: eps_p; total Lagrangian:
   *   plastic Green-Lagrange strain E_p; both are state variables. Output only: updated
   *   Lagrangian: increments accumulated with the Hughes-Winget rotation; finite strain:
   *   Lagrangian logarithmic plastic strain ln(C_p) / 2 with C_p = F^T b_e^-1 F).
   * - @ref back_stress: back stress of linear kinematic hardening (deviatoric), in the stress space
   *   of the return mapping (small strain and updated Lagrangian: Cauchy; total Lagrangian: 2nd
   *   Piola-Kirchhoff, reference configuration; finite strain: Kirchhoff, current configuration).
   * - @ref elastic_left_cauchy_green: b_e = F_e F_e^T of the multiplicative finite-strain model
   *   (the other models leave it at I).
   * - @ref deformation_gradient: F at this state (3x3; the out-of-plane stretch of plane stress,
   *   the hoop stretch of axisymmetric models); F_n of the next step for the updated Lagrangian
   *   and finite strain models.
   * - @ref equivalent_plastic_strain: accumulated equivalent plastic strain alpha.
   * - @ref temperature: the temperature the state was evaluated at (thermal scenes: the
   *   temperature field at this point at the start of the step, written by the thermal field;
   *   isothermal scenes leave it at 0 and no model reads it).
   * - @ref evaluation_temperature: the temperature of the last mechanical evaluation, i.e. the
   *   one whose thermal stretch the stored deformation gradient excludes (ThermalExpansionModel).
   *   The thermal field overwrites @ref temperature after the mechanical solve of a step, so
   *   the two differ by the step's temperature change until the next evaluation; a re-basing
   *   after mesh adaptation must use this one, or the step's thermal strain is lost.
   * - @ref plastic_work: accumulated plastic work per unit reference volume, int tau_vm d alpha
   *   (N mm / mm^3 = MPa; thermal scenes only: ThermalExpansionModel; the source of plastic
   *   heating).
   * - @ref martensite, @ref carbon: martensite volume fraction (the rest is austenite) and carbon
   *   content in wt% (scenes with `Phases/Enabled`: PhaseTransformationModel; 0 otherwise);
   *   @ref bainite: bainite volume fraction (with `Phases/Bainite start times`; 0 otherwise);
   *   @ref initial_martensite: the martensite fraction the point had at t = 0 (`Phases/Initial
   *   state = quenched`: formed in the quench before the run, part of the stress-free reference;
   *   0 otherwise): the transformation strain counts from it.
   */
  struct MaterialState
  {
    dealii::SymmetricTensor<2, 3> stress;         ///< Cauchy stress
    dealii::SymmetricTensor<2, 3> plastic_strain; ///< plastic strain measure of the model
    dealii::SymmetricTensor<2, 3> back_stress;    ///< kinematic-hardening back stress
    dealii::SymmetricTensor<2, 3> elastic_left_cauchy_green;      ///< b_e (finite strain model)
    dealii::Tensor<2, 3>          deformation_gradient;           ///< F at this state
    double                        equivalent_plastic_strain = 0.; ///< alpha
    double                        temperature = 0.; ///< temperature of the state (thermal)
    double evaluation_temperature = 0.; ///< temperature of the last evaluation (thermal)
    double plastic_work = 0.;           ///< int tau_vm d alpha (thermal)
    double martensite = 0.;             ///< martensite volume fraction (phases)
    double carbon = 0.;                 ///< carbon content, wt% (phases)
    double bainite = 0.;                ///< bainite volume fraction (phases)
    double initial_martensite = 0.;     ///< martensite fraction at t = 0 (phases)

    /** The undeformed, stress-free state: F = b_e = I, everything else zero. */
    MaterialState();

    /** Number of doubles written by pack(). */
    static constexpr unsigned int n_packed_values = 6 * 4 + 9 + 8;

    /** Append the state to @p data as n_packed_values doubles (mesh transfer, checkpoints). */
    void pack(std::vector<double> &data) const;

    /** Read the state from n_packed_values doubles starting at @p data. */
    void unpack(const double *data);

    /** von Mises equivalent of the Cauchy stress, sqrt(3/2 |dev sigma|^2). */
    double von_mises_stress() const;
  };
} // namespace ausroll::material
