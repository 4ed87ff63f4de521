/**
 * @file friction_law.h
 * Friction laws of a rigid die (`Contact/Die N/Friction`): frictionless, Coulomb, sticking,
 * Tresca (constant shear, tau = m k) and Coulomb capped by shear (tau = min(mu p, m k)).
 */
#pragma once

#include <ausroll/contact/contact_parameters.h>

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
   * s T(0) t) and the load-increment-ratio event (slip_limit()). A new law is one class here, one
   * factory line in create_friction_law() and one name in the `Friction` selection.
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

  /** `Friction = frictionless`: no tangential force, closed nodes slip. */
  class Frictionless : public FrictionLaw
  {
  public:
    std::string name() const override { return "frictionless"; }
    bool        sticks_when_closing() const override { return false; }
    bool        switches_stick_slip() const override { return false; }
    SlipLimit   slip_limit(const double, const double) const override { return SlipLimit(); }
  };

  /** `Friction = Coulomb`: T = mu R_n (`Friction coefficient` mu). */
  class CoulombFriction : public FrictionLaw
  {
  public:
    explicit CoulombFriction(const double mu)
        : mu(mu)
    {
    }
    std::string name() const override { return "Coulomb"; }
    SlipLimit   slip_limit(const double, const double) const override { return {0., mu}; }

  private:
    const double mu;
  };

  /** `Friction = sticking`: no slip (mu = infinity), closed nodes stick until they open. */
  class StickingFriction : public FrictionLaw
  {
  public:
    std::string name() const override { return "sticking"; }
    bool        switches_stick_slip() const override { return false; }
    SlipLimit   slip_limit(const double, const double) const override;
  };

  /**
   * `Friction = Tresca`: constant shear, tau = m k on the contact area whatever the pressure
   * (the friction-factor law of forming practice); T = m k A. k = sigma_0 / sqrt(3) is the shear
   * yield stress of the workpiece from its initial yield stress `Material/Yield stress` (von
   * Mises), m the `Friction factor` (0: frictionless, 1: full sticking friction of a rigid-plastic
   * workpiece).
   */
  class TrescaFriction : public FrictionLaw
  {
  public:
    /** Friction factor @p m, shear yield stress @p k. */
    TrescaFriction(const double m, const double k)
        : shear(m * k)
    {
    }
    std::string name() const override { return "Tresca"; }
    SlipLimit   slip_limit(const double, const double area) const override
    {
      return {shear * area, 0.};
    }

  private:
    const double shear; ///< m k
  };

  /**
   * `Friction = Coulomb capped by shear`: tau = min(mu p, m k), i.e. T = min(mu R_n, m k A):
   * Coulomb at low pressure, constant shear where mu p would exceed the shear the workpiece can
   * carry.
   */
  class CappedCoulombFriction : public FrictionLaw
  {
  public:
    /** Coefficient @p mu, friction factor @p m, shear yield stress @p k. */
    CappedCoulombFriction(const double mu, const double m, const double k)
        : mu(mu)
        , shear(m * k)
    {
    }
    std::string name() const override { return "Coulomb capped by shear"; }
    SlipLimit   slip_limit(const double normal_force, const double area) const override
    {
      const double cap = shear * area;
      return mu * normal_force <= cap ? SlipLimit{0., mu} : SlipLimit{cap, 0.};
    }

  private:
    const double mu;
    const double shear; ///< m k
  };

  /** The law selected by `Friction` with its parameters (@p parameters of one die). */
  std::unique_ptr<FrictionLaw> create_friction_law(const DieParameters &parameters);
} // namespace ausroll::contact
