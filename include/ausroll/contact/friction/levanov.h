/**
 * @file levanov.h
 * Friction law `Levanov` (subsection `Contact/Die N/Levanov`): the pressure-dependent shear
 * friction of bulk forming codes, tau = m k (1 - exp(-1.25 p / sigma_0)).
 *
 * Source: A. N. Levanov, V. L. Kolmogorov, S. P. Burkin et al., Kontaktnoe trenie v protsessakh
 * obrabotki metallov davleniem (Contact friction in metal forming processes), Metallurgiya,
 * Moscow, 1976; the law as used by the forming code QForm ("Levanov friction law").
 */
#pragma once

#include <ausroll/contact/friction/tresca.h>
#include <ausroll/contact/friction_law.h>

#include <memory>
#include <string>

namespace ausroll::contact
{
  /**
   * `Friction = Levanov`: tau(p) = m k (1 - exp(-1.25 p / sigma_0)) with the friction factor m,
   * the shear yield stress k = sigma_0 / sqrt(3) and the initial yield stress sigma_0 of the
   * workpiece. At low pressure it is Coulomb-like, tau ~ 1.25 m k p / sigma_0 = (1.25 m / sqrt(3))
   * p; at high pressure it tends to the Tresca shear m k. In nodal forces (p = R_n / A):
   * T(R_n) = m k A (1 - exp(-c R_n / A)), c = 1.25 / sigma_0; slip_limit() returns the tangent
   * line of T at R_n (exact value, exact slope dT/dR_n = m k c exp(-c R_n / A)). A node in
   * tension (R_n <= 0) gets the tangent at 0, as a Coulomb law would give it.
   */
  class LevanovFriction : public FrictionLaw
  {
  public:
    /** The exponent factor 1.25 of the law. */
    static constexpr double exponent_factor = 1.25;

    /** Friction factor @p m, shear yield stress @p k > 0. */
    LevanovFriction(double m, double k);

    std::string name() const override { return "Levanov"; }
    SlipLimit   slip_limit(double normal_force, double area) const override;

    /** The shear stress tau(p) of the law at contact pressure @p pressure. */
    double shear_stress(double pressure) const;

  private:
    const double shear; ///< m k, the limit at high pressure
    const double c;     ///< 1.25 / sigma_0 = 1.25 / (sqrt(3) k)
  };

  /** Subsection `Levanov`. */
  using LevanovParameters = FrictionFactorParameters<LevanovFriction>;
} // namespace ausroll::contact
