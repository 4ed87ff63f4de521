/**
 * @file transformation_plasticity.h
 * The mechanics of the phase transformation seen by the return map: transformation-induced
 * plasticity (TRIP) and the mixture rule of the yield stress (entries of subsection `Phases`).
 */
#pragma once

#include <ausroll/material/material_state.h>
#include <ausroll/material/phase_property.h>

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace ausroll::material
{
  /**
   * The entries of `Phases` that change the return map (declared and read inside the subsection
   * by PhaseParameters). All are off by default, and then the return map is the one without
   * phases, bit for bit.
   */
  struct TransformationPlasticityParameters
  {
    double trip_coefficient = 0.; ///< `TRIP coefficient` K (1/MPa), 0: no TRIP
    /** `Martensite yield stress` sigma_y,M(C, T) (MPa): a number, a table in T or an expression
        of C and T. */
    PhaseProperty martensite_yield_stress;
    bool          martensite_yield_given = false; ///< the entry is not empty
    /** `Martensite hardening modulus` H_M(C, T) (MPa; empty: perfectly plastic martensite). */
    PhaseProperty martensite_hardening_modulus;
    PhaseProperty bainite_yield_stress;        ///< `Bainite yield stress` sigma_y,B(C, T) (MPa)
    bool          bainite_yield_given = false; ///< the entry is not empty

    /** Declare the entries (the caller has entered subsection `Phases`). */
    static void declare_parameters(dealii::ParameterHandler &prm);

    /** Read the entries (inside subsection `Phases`); InputError naming `Phases/<entry>` for a
        negative K, a bad table or expression, or a hardening modulus without the martensite's
        yield stress. @p directory resolves `file:` tables. */
    void parse_parameters(dealii::ParameterHandler &prm, const std::string &directory);

    /** True if TRIP or the mixture rule changes the return map. */
    bool active() const
    {
      return trip_coefficient > 0. || martensite_yield_given || bainite_yield_given
             || martensite_hardening_modulus.given();
    }
  };

  /**
   * The phase fractions of one step at a material point: martensite and bainite at its start
   * (the committed state) and at its end (the trial state, which PhaseTransformationModel fills
   * before the kinematics run: the kinetics are explicit, so the fractions are known before the
   * stress), and the point's carbon content (the product phases' properties in C). Without
   * phases all are 0.
   */
  struct PhaseStep
  {
    double martensite_old = 0.; ///< f_M,n
    double bainite_old = 0.;    ///< f_B,n
    double martensite = 0.;     ///< f_M,n+1
    double bainite = 0.;        ///< f_B,n+1
    double carbon = 0.;         ///< C (wt%)

    /** The step from @p old (committed) to @p state (trial). */
    static PhaseStep of(const MaterialState &old, const MaterialState &state)
    {
      return {old.martensite, old.bainite, state.martensite, state.bainite, state.carbon};
    }

    /** No transformation during the step, at the fractions of @p state (yield checks). */
    static PhaseStep at(const MaterialState &state)
    {
      return {state.martensite, state.bainite, state.martensite, state.bainite, state.carbon};
    }
  };

  /**
   * TRIP and the mixture rule of the yield stress, as the von Mises return map uses them.
   *
   * - TRIP (Leblond, Devaux and Devaux 1989, Int. J. Plasticity 5, 551-572, the linear regime
   *   h(sigma_eq / sigma_y) = 1): d eps_tp = 3/2 K s phi'(z) dz with the deviatoric stress s,
   *   the fraction z = f_M + f_B transformed from austenite and phi(z) = z (1 - ln z)
   *   (phi(0) = 0, phi(1) = 1, phi'(z) = -ln z). Integrated over a step with s at its end
   *   (backward Euler in s, exact in z): Delta eps_tp = kappa s, kappa = 3/2 K (phi(z_n+1) -
   *   phi(z_n)); under a constant uniaxial stress sigma the axial TRIP strain is K sigma
   *   phi(z), K sigma after the full transformation.
   * - mixture rule (linear): sigma_y = (1 - f_M - f_B) sigma_y,A(alpha, T) + f_M (sigma_y,M(C, T)
   *   + H_M(C, T) alpha) + f_B sigma_y,B(C, T) with sigma_y,A the hardening law of `Material`
   *   (the austenite), the product phases at their `Martensite yield stress`/`Bainite yield
   *   stress` (numbers, tables in T or expressions of the point's carbon content C and T), the
   *   martensite with the linear `Martensite hardening modulus` H_M in the point's accumulated
   *   alpha (0: perfectly plastic; alpha counts the austenite's plastic strain too: the new
   *   martensite inherits all of it), bainite perfectly plastic; a phase whose yield entry is
   *   empty yields as the austenite (its fraction joins the austenite's weight).
   */
  class TransformationPlasticity
  {
  public:
    /** From the `Phases` entries @p parameters. */
    explicit TransformationPlasticity(const TransformationPlasticityParameters &parameters);

    /** Leblond's phi(z) = z (1 - ln z), 0 at z = 0. */
    static double leblond_phi(const double z);

    /** kappa of the step: Delta eps_tp = kappa s (1/MPa; 0 without TRIP or transformation). */
    double trip_compliance(const PhaseStep &phases) const;

    /** The weight of the austenite's hardening law in the mixture at the end of the step. */
    double austenite_weight(const PhaseStep &phases) const;

    /** f_M sigma_y,M(C, T) + f_B sigma_y,B(C, T) at the end of the step (the phases with an
        entry). */
    double product_yield_stress(const PhaseStep &phases, const double temperature) const;

    /** f_M H_M(C, T) at the end of the step: the products' share of d sigma_y / d alpha (0
        without `Martensite hardening modulus`). */
    double product_hardening(const PhaseStep &phases, const double temperature) const;

    /** True if the products harden (`Martensite hardening modulus` given). */
    bool products_harden() const { return parameters.martensite_hardening_modulus.given(); }

  private:
    TransformationPlasticityParameters parameters; ///< K and the product phases' tables
  };
} // namespace ausroll::material
