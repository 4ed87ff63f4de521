/**
 * @file phase_transformation_model.h
 * Martensitic transformation of metastable austenite on cooling, and its volume change, around
 * any constitutive model (subsection `Phases`).
 */
#pragma once

#include <ausroll/material/bainite_kinetics.h>
#include <ausroll/material/carbon_function.h>
#include <ausroll/material/material_point.h>
#include <ausroll/material/transformation_plasticity.h>
#include <ausroll/material/wrapped_model.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_point_data.h>
#include <deal.II/grid/tria.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ausroll::material
{
  /** The `Phases` subsection (martensite kinetics and transformation strain). */
  struct PhaseParameters
  {
    bool enabled = false; ///< `Enabled`
    /** `Initial state = quenched`: the points whose Ms(C) lies above the initial temperature
        start with their Koistinen-Marburger martensite fraction (initialize_phase_state()). */
    bool quenched = false;
    /** `Initial state = undercooled austenite`: all austenite even below Ms(C) (no check). */
    bool undercooled = false;
    /** `Carbon content` (wt%): an expression of x, y, z and depth, or `file: NAME.csv` of C
        against depth (material::CarbonProfile). */
    std::string carbon_content = "0.2";
    /** `Case boundaries`: the boundary ids whose initial outline the depth is measured from
        (empty: the Candidate boundaries of the dies). */
    std::vector<unsigned int> case_boundaries;
    /** `Martensite start temperature` Ms(C), expression of C (wt%); default Andrews' linear
        relation with the other elements of AISI 9310. */
    std::string martensite_start = "539 - 423*C - 30.4*0.55 - 17.7*3.25 - 12.1*1.2 - 7.5*0.12";
    double      koistinen_marburger = 0.011; ///< `Koistinen-Marburger coefficient` b (1/K)
    /** `Transformation volume change` austenite to martensite in per cent, expression of C. */
    std::string volume_change = "4.64 - 0.53*C";
    /** `Bainite start times` t_s(T) of the TTT diagram (s; a table in T, empty: no bainite). */
    std::string bainite_start;
    /** `Bainite finish times` t_f(T) (s; the same temperatures as the start times). */
    std::string bainite_finish;
    /** `Bainite volume change` austenite to bainite in per cent, expression of C. */
    std::string bainite_volume_change = "4.64 - 1.43*C";
    /** `TRIP coefficient`, `Martensite yield stress`, `Martensite hardening modulus`, `Bainite
        yield stress`: the mechanics of the transformation in the return map
        (TransformationPlasticity). */
    TransformationPlasticityParameters mechanics;
    /** `TRIP heating`: the TRIP dissipation joins the plastic work that heats the workpiece. */
    bool trip_heating = false;
    /** `Latent heat` of martensite per unit mass (mm^2/s^2, the unit of Thermal/Specific heat
        times K: 1 J/g = 1e9 mm^2/s^2), released as martensite forms (the thermal source). */
    double latent_heat = 0.;
    /** `Bainite latent heat` per unit mass (mm^2/s^2). */
    double bainite_latent_heat = 0.;
    /** `Mechanical stabilisation`: prior plastic strain of the austenite lowers Ms. */
    bool mechanical_stabilisation = false;
    /** `Stabilisation energy` G_0 (J/mol): mu b sqrt(rho_0) V_m / (8 pi (1 - nu)). */
    double stabilisation_energy = 35.11;
    /** `Stabilisation strain` eps_0 = rho_0 / (d rho / d eps). */
    double stabilisation_strain = 0.1;
    /** `Driving force slope` S = -d Delta G / dT near Ms (J/(mol K)). */
    double driving_force_slope = 6.94;
    /** Folder of the `.prm` file (resolves `file:` tables). */
    std::string input_directory;

    static void declare_parameters(dealii::ParameterHandler &prm);

    /** Read the subsection; @p thermal: `Thermal/Enabled` (phases need the temperature);
        @p directory: the `.prm` file's folder. */
    void parse_parameters(dealii::ParameterHandler &prm,
                          const bool                thermal,
                          const std::string        &directory = "");

    /** True if the bainite kinetics are given. */
    bool has_bainite() const { return enabled && !bainite_start.empty(); }
  };

  /**
   * Wraps a ConstitutiveModel (any kinematics, usually a ThermalExpansionModel) with the
   * martensitic transformation of the austenite:
   * - kinetics (Koistinen and Marburger 1959): the martensite fraction at the temperature T of
   *   the state (old.temperature, as the thermal strain) is f = 1 - exp(-b (Ms(C) - T)) below Ms,
   *   irreversible (it never decreases, nothing forms on heating or above Ms); explicit, like the
   *   thermal strain: the mechanical step sees the fraction of the temperature of its start;
   * - transformation strain: the isotropic volume change f dV/V(C) of the fraction transformed,
   *   as a stretch theta_tr = (1 + f dV/V)^(1/3) (multiplicative, as ThermalExpansionModel:
   *   P = theta_tr^2 P_inner(F / theta_tr), dP/dF = theta_tr dP_inner/dF) or, in small strain,
   *   additive (theta_tr - 1) I.
   * - bainite (optional, `Bainite start times`/`Bainite finish times`): BainiteKinetics (JMAK
   *   through the TTT start and finish times, additivity rule) over the step length
   *   set_step_length() at the temperature of the state, of the austenite not transformed to
   *   martensite: f_B = xi (1 - f_M) with xi the kinetics' share; martensite then forms from the
   *   austenite left, f_M = max(f_M,old, (1 - f_B) KM(T)); its volume change f_B dV_B/V(C) adds
   *   to the martensite's in the stretch theta_tr = (1 + f_M dV_M/V + f_B dV_B/V)^(1/3).
   * - the fractions of the step are written into the trial state before the inner model runs:
   *   its return map reads them (PhaseStep::of(old, state)) for TRIP and the mixture rule of the
   *   yield stress (`TRIP coefficient`, `Martensite yield stress`, TransformationPlasticity).
   * - TRIP heating (`TRIP heating`, off by default): the TRIP dissipation of the step,
   *   J kappa dev(sigma) : dev(sigma) per unit reference volume (Delta eps_tp = kappa dev sigma
   *   with sigma the Cauchy stress at the end of the step; exact in small strain), is added to
   *   state.plastic_work after the inner model (ThermalExpansionModel) has written the plastic
   *   part, so the heat source beta (W_n+1 - W_n) / dt counts it with the Taylor-Quinney factor.
   * - mechanical stabilisation (`Mechanical stabilisation`, off by default; Chatterjee, Wang
   *   and Bhadeshia 2006 in the form of the MUCG46 program): the accumulated equivalent plastic
   *   strain alpha of the state at the start of the step raises the driving force martensite
   *   needs by the work of moving its interface through the forest of dislocations,
   *   G(alpha) = G_0 (sqrt(1 + alpha / eps_0) - 1) (J/mol), which lowers Ms by G / S:
   *   Ms(C, alpha) = Ms(C) - G_0 / S (sqrt(1 + alpha / eps_0) - 1).
   * Not yet: the hardening memory of the austenite.
   */
  class PhaseTransformationModel : public WrappedModel
  {
  public:
    PhaseTransformationModel(std::unique_ptr<ConstitutiveModel> inner,
                             const PhaseParameters             &parameters);

    void evaluate(const dealii::Tensor<2, 3> &F,
                  const MaterialState        &old,
                  MaterialState              &state,
                  dealii::Tensor<2, 3>       &P,
                  dealii::Tensor<4, 3>       *tangent) const override;

    void rebase(MaterialState &state, const dealii::Tensor<2, 3> &F) const override;

    /** After a polynomial mesh transfer: the phase fractions back into [0, 1] (the initial
        martensite not above the martensite, martensite and bainite not above 1) and the carbon
        content not negative, then the inner model's stress projection. */
    void make_admissible(MaterialState &state) const override;

    /** The length of the step the next evaluations belong to (the bainite kinetics). */
    void set_step_length(const double dt) override
    {
      step_length = dt;
      WrappedModel::set_step_length(dt);
    }

    /** Ms at carbon content @p C (wt%) after the accumulated plastic strain @p alpha (the
        mechanical stabilisation; without it Ms(C)). */
    double martensite_start(const double C, const double alpha = 0.) const;

    /** Martensite fraction after a step at temperature @p T from fraction @p f_old, with the
        bainite fraction @p bainite (not available to martensite), after the accumulated
        plastic strain @p alpha (the mechanical stabilisation's). */
    double martensite_fraction(const double f_old,
                               const double C,
                               const double T,
                               const double bainite = 0.,
                               const double alpha = 0.) const;

    /** Bainite fraction after a step of length @p dt at @p T from @p f_old, with the martensite
        fraction @p martensite of the step's start. */
    double bainite_fraction(const double f_old,
                            const double martensite,
                            const double T,
                            const double dt) const;

    /** theta_tr of martensite fraction @p f and bainite fraction @p f_b at carbon @p C, relative
        to the stress-free reference that holds the martensite fraction @p f_0 (the quenched
        initial state; 0: pure austenite). */
    double transformation_stretch(const double f,
                                  const double C,
                                  const double f_b = 0.,
                                  const double f_0 = 0.) const;

  private:
    BainiteKinetics               bainite;          ///< TTT kinetics (may be inactive)
    std::optional<CarbonFunction> dv_bainite;       ///< dV/V(C) of bainite, per cent
    double                        step_length = 0.; ///< dt of the current step

    /** TRIP of the TRIP heating (empty: the TRIP dissipation is not counted as heat). */
    std::optional<TransformationPlasticity> trip_heat;

    bool   stabilised = false;        ///< `Mechanical stabilisation`
    double stabilisation_shift = 0.;  ///< G_0 / S (K)
    double stabilisation_strain = 1.; ///< eps_0

    double         b;  ///< Koistinen-Marburger coefficient (1/K)
    CarbonFunction ms; ///< Ms(C)
    CarbonFunction dv; ///< dV/V(C) in per cent
  };

  /**
   * The phase state at t = 0, from the carbon content and the temperature of every point's
   * committed state (both set before): with `Initial state = quenched` the points whose Ms(C)
   * lies above their temperature T_0 start with the Koistinen-Marburger fraction
   * f_0 = 1 - exp(-b (Ms(C) - T_0)) as martensite and as initial_martensite (the stress-free
   * reference: the transformation strain counts from it), the others as austenite; committed
   * and trial alike. With `Initial state = austenite` a point below Ms(C) is an InputError
   * naming Phases/Initial state (collective over @p comm: every rank throws the same);
   * `undercooled austenite` leaves every point austenite without that check.
   */
  template <int dim>
  void
  initialize_phase_state(const PhaseParameters                  &parameters,
                         const dealii::Triangulation<dim>       &triangulation,
                         dealii::CellDataStorage<typename dealii::Triangulation<dim>::cell_iterator,
                                                 MaterialPoint> &points,
                         const MPI_Comm                          comm);
} // namespace ausroll::material
