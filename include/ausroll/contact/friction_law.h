/**
 * @file friction_law.h
 * The friction law of a rigid die (`Contact/Die N/Friction`): the interface FrictionLaw, the
 * parameters of a law (FrictionParameters, one subsection per law) and their registry. The laws
 * are in contact/friction/, one file pair each: frictionless, Coulomb, sticking, Tresca (constant
 * shear, tau = m k), Coulomb capped by shear (tau = min(mu p, m k)) and Levanov
 * (tau = m k (1 - exp(-1.25 p / sigma_0))).
 */
#pragma once

#include <ausroll/contact/contact_parameters.h>
#include <ausroll/core/registry.h>
#include <ausroll/material/material_parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <memory>
#include <string>

namespace ausroll::contact
{
  /**
   * The force limit of a slipping node as an affine function of its normal force R_n near the
   * current state: T(R_n) = intercept + slope R_n (Coulomb: 0 + mu R_n; Tresca: m k A + 0 R_n).
   * The piece is exact for every law except at the kink of the capped law, where the piece of the
   * side the node is on is returned.
   */
  struct SlipLimit
  {
    double intercept = 0.; ///< T(0) of the affine piece (N)
    double slope = 0.;     ///< dT / dR_n (dimensionless)

    /** T(R_n) of this piece. */
    double value(const double normal_force) const { return intercept + slope * normal_force; }
  };

  /**
   * Answer of a friction law to a trial tangential force (the return map of friction, in the
   * manner of plasticity): stick if the trial force is admissible, else slip on the limit.
   */
  struct FrictionResponse
  {
    bool   slip = false;    ///< true: the trial force exceeds the limit, the node slips
    double tangential = 0.; ///< admissible tangential force (trial if stick, +-T(R_n) if slip)
    double d_d_normal = 0.; ///< d tangential / d R_n
    double d_d_trial = 1.;  ///< d tangential / d trial (1 stick, 0 slip)
  };

  /**
   * A friction law between the workpiece and a rigid die: the magnitude T of the tangential force
   * at which a contact node slips, given its normal force R_n (> 0 in compression) and tributary
   * area A (reference area of the node's shape function, times 2 pi r in axisymmetric models).
   * Everything is in nodal forces; with A = 1 the same calls read as tractions (T = tau, R_n = p).
   *
   * Used by ContactOperator at one site per use: the status of a closing node
   * (sticks_when_closing()), the stick -> slip test and the slip force (respond(), slip_limit()),
   * the consistent row transform of a slipping node (slip_limit(): I + s T' t (x) n and the offset
   * s T(0) t) and the load-increment-ratio event (slip_limit()). A new law is one file pair
   * contact/friction/<law>.{h,cc}: the law and its FrictionParameters, registered with
   * AUSROLL_REGISTER_FRICTION_LAW; the `Friction` selection and its subsection follow.
   */
  class FrictionLaw
  {
  public:
    virtual ~FrictionLaw() = default;

    /** Name as in `Friction`. */
    virtual std::string name() const = 0;

    /** True if a node that closes sticks (every law except frictionless, where it slips). */
    virtual bool sticks_when_closing() const { return true; }

    /**
     * True if closed nodes switch between stick and slip by the slip limit (Coulomb, Tresca,
     * capped); false if they always slip (frictionless) or always stick (sticking).
     */
    virtual bool switches_stick_slip() const { return true; }

    /** The affine piece of the slip limit at normal force @p normal_force, area @p area. */
    virtual SlipLimit slip_limit(const double normal_force, const double area) const = 0;

    /**
     * Stick or slip for the trial tangential force @p trial at normal force @p normal_force:
     * slip if switches_stick_slip() and |trial| > T(R_n) + @p tolerance, or if the law never
     * sticks; the slip force has the sign of the trial force and magnitude T(R_n).
     */
    FrictionResponse respond(const double normal_force,
                             const double trial,
                             const double area,
                             const double tolerance = 0.) const;
  };

  /** What a friction law may need from the workpiece (handed to its factory by the scene). */
  struct FrictionContext
  {
    /** Shear yield stress k = sigma_0 / sqrt(3) of the workpiece's initial yield stress
        (`Material/Yield stress`); 0 for an elastic workpiece. */
    double shear_yield_stress = 0.;
    /** True if `Material/Yield stress` is a table in temperature (no single k: the shear laws
        refuse it). */
    bool yield_stress_depends_on_temperature = false;
  };

  /** The context of a workpiece of material @p material: k = sigma_0 / sqrt(3) of its initial
      yield stress (forming practice), 0 for an elastic workpiece. */
  FrictionContext friction_context(const material::MaterialParameters &material);

  /**
   * The parameters of one friction law: the entries of its own subsection `Contact/Die N/<Law>`
   * (none for frictionless and sticking), registered in FrictionRegistry with
   * AUSROLL_REGISTER_FRICTION_LAW at the end of the law's own `.cc` (contact/friction/).
   */
  class FrictionParameters : public RegisteredParameters
  {
  public:
    /** True if these parameters make the law frictionless (a zero coefficient or factor):
        closed nodes then slip freely (the Frictionless law is created instead). */
    virtual bool frictionless() const { return false; }

    /** The law; InputError naming the entry under @p die_path ("Contact/Die 0/") if it cannot
        be made with @p context. */
    virtual std::unique_ptr<FrictionLaw> create(const FrictionContext &context,
                                                const std::string     &die_path) const = 0;
  };

  /** The registry of the friction laws (`Contact/Die N/Friction`). */
  using FrictionRegistry = Registry<FrictionParameters>;

  /**
   * k of @p context for a law that needs the shear yield stress; InputError naming
   * `<die_path>Friction` if the workpiece is elastic (k = 0).
   */
  double required_shear_yield_stress(const FrictionContext &context, const std::string &die_path);

  /**
   * The law of die @p parameters (`Friction` and its subsection): Frictionless if its parameters
   * say so, else the registered law's create(); @p die_path ("Contact/Die 0/") for messages.
   */
  std::unique_ptr<FrictionLaw> create_friction_law(const DieParameters   &parameters,
                                                   const FrictionContext &context,
                                                   const std::string     &die_path);
} // namespace ausroll::contact

/** Register the friction-law parameters @p Class (see AUSROLL_REGISTER). */
#define AUSROLL_REGISTER_FRICTION_LAW(Class, name, subsection, description) \
  AUSROLL_REGISTER(::ausroll::contact::FrictionParameters, Class, name, subsection, description)
