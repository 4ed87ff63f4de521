/**
 * @file test_friction_law.cc
 * Unit tests of the friction laws (contact/friction_law.h): for each law the answer to a trial
 * tangential force (stick or slip, the admissible force) against the closed-form law, the
 * derivatives against central differences, and the `Friction` entries (registry, one subsection
 * per law, zero coefficients, k = sigma_0 / sqrt(3) handed in through the factory, the message
 * for an elastic workpiece). Levanov against its closed form and its limits p -> 0, p -> infinity.
 */
#include <ausroll/contact/contact_parameters.h>
#include <ausroll/contact/friction/capped_coulomb.h>
#include <ausroll/contact/friction/coulomb.h>
#include <ausroll/contact/friction/frictionless.h>
#include <ausroll/contact/friction/levanov.h>
#include <ausroll/contact/friction/sticking.h>
#include <ausroll/contact/friction/tresca.h>
#include <ausroll/contact/friction_law.h>
#include <ausroll/core/exceptions.h>

#include <deal.II/base/parameter_handler.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

using namespace ausroll::contact;

namespace
{
  /** Central differences of respond().tangential in R_n and in the trial force (h = 1e-6: the
      laws are piecewise affine, so away from a kink the difference is exact to round-off). */
  void expect_derivatives(const FrictionLaw &law,
                          const double       normal,
                          const double       trial,
                          const double       area)
  {
    const double           h = 1e-6;
    const FrictionResponse r = law.respond(normal, trial, area);
    const double           d_normal = (law.respond(normal + h, trial, area).tangential
                             - law.respond(normal - h, trial, area).tangential)
                            / (2. * h);
    const double d_trial = (law.respond(normal, trial + h, area).tangential
                            - law.respond(normal, trial - h, area).tangential)
                           / (2. * h);
    EXPECT_NEAR(r.d_d_normal, d_normal, 1e-8) << law.name() << " at R_n " << normal;
    EXPECT_NEAR(r.d_d_trial, d_trial, 1e-8) << law.name() << " at R_n " << normal;
  }

  /** Contact parameters of one die with the given `Friction` lines. */
  ContactParameters parse_die(const std::string &friction_lines)
  {
    dealii::ParameterHandler prm;
    ContactParameters::declare_parameters(prm);
    prm.parse_input_from_string("subsection Contact\n set Number of dies = 1\n"
                                " subsection Die 0\n"
                                + friction_lines + " end\nend\n");
    ContactParameters p;
    p.parse_parameters(prm, "");
    return p;
  }
} // namespace

TEST(FrictionLaw, Frictionless)
{
  const Frictionless law;
  EXPECT_FALSE(law.sticks_when_closing());
  EXPECT_FALSE(law.switches_stick_slip());
  const FrictionResponse r = law.respond(100., 30., 2.);
  EXPECT_TRUE(r.slip);
  EXPECT_EQ(r.tangential, 0.);
  EXPECT_EQ(r.d_d_normal, 0.);
  EXPECT_EQ(r.d_d_trial, 0.);
  expect_derivatives(law, 100., 30., 2.);
}

TEST(FrictionLaw, Coulomb)
{
  const CoulombFriction law(0.2);
  EXPECT_TRUE(law.sticks_when_closing());
  EXPECT_TRUE(law.switches_stick_slip());
  // |t| <= mu p: stick, the trial force stays
  FrictionResponse r = law.respond(100., 19.9, 3.);
  EXPECT_FALSE(r.slip);
  EXPECT_EQ(r.tangential, 19.9);
  EXPECT_EQ(r.d_d_trial, 1.);
  EXPECT_EQ(r.d_d_normal, 0.);
  // beyond: slip on the cone with the sign of the trial force, independent of the area
  r = law.respond(100., -30., 3.);
  EXPECT_TRUE(r.slip);
  EXPECT_DOUBLE_EQ(r.tangential, -20.);
  EXPECT_DOUBLE_EQ(r.d_d_normal, -0.2);
  EXPECT_EQ(r.d_d_trial, 0.);
  EXPECT_DOUBLE_EQ(law.respond(100., -30., 7.).tangential, -20.);
  // the tolerance widens the cone
  EXPECT_FALSE(law.respond(100., 20.5, 1., 1.).slip);
  EXPECT_TRUE(law.respond(100., 20.5, 1., 0.).slip);
  const SlipLimit limit = law.slip_limit(100., 3.);
  EXPECT_EQ(limit.intercept, 0.);
  EXPECT_EQ(limit.slope, 0.2);
  expect_derivatives(law, 100., 10., 1.);
  expect_derivatives(law, 100., 30., 1.);
  expect_derivatives(law, 100., -30., 1.);
}

TEST(FrictionLaw, Sticking)
{
  const StickingFriction law;
  EXPECT_TRUE(law.sticks_when_closing());
  EXPECT_FALSE(law.switches_stick_slip());
  const FrictionResponse r = law.respond(1., 1e12, 1.);
  EXPECT_FALSE(r.slip);
  EXPECT_EQ(r.tangential, 1e12);
  EXPECT_TRUE(std::isinf(law.slip_limit(1., 1.).value(1.)));
  expect_derivatives(law, 1., 50., 1.);
}

TEST(FrictionLaw, TrescaConstantShear)
{
  // m = 0.5, k = 240 / sqrt(3): tau = 69.28 MPa whatever the pressure; the force is tau A
  const double         k = 240. / std::sqrt(3.), m = 0.5;
  const TrescaFriction law(m, k);
  EXPECT_TRUE(law.sticks_when_closing());
  EXPECT_TRUE(law.switches_stick_slip());
  const double area = 0.25;
  for (const double p : {1e-3, 1., 1e3, 1e6})
  {
    const FrictionResponse r = law.respond(p * area, 1e3, area);
    EXPECT_TRUE(r.slip);
    EXPECT_NEAR(r.tangential, m * k * area, 1e-13 * m * k * area);
    EXPECT_EQ(r.d_d_normal, 0.);
    EXPECT_EQ(r.d_d_trial, 0.);
  }
  EXPECT_FALSE(law.respond(10., 0.99 * m * k * area, area).slip);
  EXPECT_NEAR(law.respond(10., -1e3, 2. * area).tangential, -2. * m * k * area, 1e-12);
  // with A = 1 the calls read as tractions
  EXPECT_NEAR(law.respond(5., 100., 1.).tangential, m * k, 1e-12);
  expect_derivatives(law, 10., 1e3, area);
  expect_derivatives(law, 10., 1., area);
}

TEST(FrictionLaw, CoulombCappedByShear)
{
  const double                mu = 0.2, m = 0.5, k = 240. / std::sqrt(3.), area = 2.;
  const CappedCoulombFriction law(mu, m, k);
  const double                kink = m * k * area / mu; // R_n where mu R_n = m k A
  // below the kink: Coulomb
  FrictionResponse r = law.respond(0.5 * kink, 1e6, area);
  EXPECT_TRUE(r.slip);
  EXPECT_NEAR(r.tangential, mu * 0.5 * kink, 1e-12 * kink);
  EXPECT_DOUBLE_EQ(r.d_d_normal, mu);
  // above: the shear cap m k A
  r = law.respond(3. * kink, -1e6, area);
  EXPECT_TRUE(r.slip);
  EXPECT_NEAR(r.tangential, -m * k * area, 1e-12 * m * k * area);
  EXPECT_EQ(r.d_d_normal, 0.);
  // continuous at the kink; tau = min(mu p, m k) at any pressure
  EXPECT_NEAR(law.respond(kink * (1. - 1e-12), 1e6, area).tangential,
              law.respond(kink * (1. + 1e-12), 1e6, area).tangential,
              1e-9 * m * k * area);
  for (const double p : {1., 100., 346., 347., 1000.})
    EXPECT_NEAR(law.respond(p * area, 1e6, area).tangential,
                std::min(mu * p, m * k) * area,
                1e-12 * m * k * area);
  // stick inside the limit
  EXPECT_FALSE(law.respond(3. * kink, 0.9 * m * k * area, area).slip);
  expect_derivatives(law, 0.5 * kink, 1e6, area);
  expect_derivatives(law, 3. * kink, -1e6, area);
  expect_derivatives(law, 3. * kink, 1., area);
}

TEST(FrictionLaw, ParametersAndFactory)
{
  const std::string die = "Contact/Die 0/";
  // k = sigma_0 / sqrt(3) of a von Mises workpiece with sigma_0 = 300
  ausroll::material::MaterialParameters material;
  material.yield_stress = 300.;
  const FrictionContext plastic = friction_context(material);
  EXPECT_DOUBLE_EQ(plastic.shear_yield_stress, 300. / std::sqrt(3.));
  material.yield_criterion = ausroll::material::YieldCriterion::none;
  const FrictionContext elastic = friction_context(material);
  EXPECT_EQ(elastic.shear_yield_stress, 0.);

  // every law is registered, in name order, and the selection lists them
  EXPECT_EQ(FrictionRegistry::instance().selection(),
            "Coulomb|Coulomb capped by shear|Levanov|Tresca|frictionless|sticking");

  ContactParameters p
      = parse_die("  set Friction = Coulomb\n  subsection Coulomb\n   set Friction coefficient = "
                  "0.3\n  end\n");
  EXPECT_EQ(create_friction_law(p.dies[0], plastic, die)->name(), "Coulomb");
  EXPECT_EQ(create_friction_law(p.dies[0], plastic, die)->slip_limit(10., 1.).slope, 0.3);
  p = parse_die("  set Friction = Coulomb\n"); // mu = 0: frictionless
  EXPECT_TRUE(p.dies[0].friction->frictionless());
  EXPECT_EQ(create_friction_law(p.dies[0], plastic, die)->name(), "frictionless");
  p = parse_die("  set Friction = sticking\n");
  EXPECT_EQ(create_friction_law(p.dies[0], elastic, die)->name(), "sticking");
  p = parse_die("  set Friction = frictionless\n");
  EXPECT_EQ(create_friction_law(p.dies[0], elastic, die)->name(), "frictionless");

  // Tresca: k through the factory
  p = parse_die("  set Friction = Tresca\n  subsection Tresca\n   set Friction factor = 0.4\n"
                "  end\n");
  auto law = create_friction_law(p.dies[0], plastic, die);
  EXPECT_EQ(law->name(), "Tresca");
  EXPECT_NEAR(law->slip_limit(0., 2.).value(0.), 2. * 0.4 * 300. / std::sqrt(3.), 1e-12);

  p = parse_die("  set Friction = Coulomb capped by shear\n"
                "  subsection Coulomb capped by shear\n   set Friction coefficient = 0.2\n"
                "   set Friction factor = 0.4\n  end\n");
  law = create_friction_law(p.dies[0], plastic, die);
  EXPECT_EQ(law->name(), "Coulomb capped by shear");
  EXPECT_DOUBLE_EQ(law->slip_limit(1., 1.).slope, 0.2);
  EXPECT_EQ(law->slip_limit(1e6, 1.).slope, 0.);

  p = parse_die("  set Friction = Levanov\n  subsection Levanov\n   set Friction factor = 0.4\n"
                "  end\n");
  law = create_friction_law(p.dies[0], plastic, die);
  EXPECT_EQ(law->name(), "Levanov");
  EXPECT_NEAR(law->slip_limit(1e9, 1.).value(1e9), 0.4 * 300. / std::sqrt(3.), 1e-9);

  p = parse_die("  set Friction = Tresca\n"); // m = 0: frictionless, also on an elastic workpiece
  EXPECT_EQ(create_friction_law(p.dies[0], elastic, die)->name(), "frictionless");

  // an elastic workpiece has no k: the message names the entry
  // (each law's subsection declares only its own entries)
  for (const auto &[law_name, entries] : std::vector<std::pair<std::string, std::string>>{
           {"Tresca", "   set Friction factor = 0.4\n"},
           {"Coulomb capped by shear",
            "   set Friction coefficient = 0.1\n   set Friction factor = 0.4\n"},
           {"Levanov", "   set Friction factor = 0.4\n"}})
  {
    p = parse_die("  set Friction = " + law_name + "\n  subsection " + law_name + "\n" + entries
                  + "  end\n");
    try
    {
      create_friction_law(p.dies[0], elastic, die);
      ADD_FAILURE() << "no InputError for " << law_name << " on an elastic workpiece";
    }
    catch (const ausroll::InputError &e)
    {
      EXPECT_NE(std::string(e.what()).find("Contact/Die 0/Friction"), std::string::npos)
          << e.what();
    }
  }
  // out of range
  dealii::ParameterHandler prm;
  ContactParameters::declare_parameters(prm);
  EXPECT_ANY_THROW(
      prm.parse_input_from_string("subsection Contact\n subsection Die 0\n  subsection "
                                  "Tresca\n   set Friction factor = 1.5\n  end\n end\nend\n"));
  // the old flat entries name their new place
  const auto moved = ContactParameters::moved_entries();
  EXPECT_NE(moved.at("Contact/Die 0/Friction coefficient").find("Contact/Die 0/Coulomb/"),
            std::string::npos);
  EXPECT_NE(moved.at("Contact/Die 2/Friction factor").find("Contact/Die 2/Levanov/"),
            std::string::npos);
}

// Levanov, tau = m k (1 - exp(-1.25 p / sigma_0)), k = sigma_0 / sqrt(3): the closed form at one
// pressure, the limits p -> 0 (Coulomb-like, mu_0 = 1.25 m / sqrt(3)) and p -> infinity (Tresca,
// m k), and the nodal slip limit (value and slope of T(R_n) = A tau(R_n / A)).
TEST(FrictionLaw, Levanov)
{
  const double          sigma_0 = 300., k = sigma_0 / std::sqrt(3.), m = 0.6, area = 2.5;
  const LevanovFriction law(m, k);
  EXPECT_TRUE(law.sticks_when_closing());
  EXPECT_TRUE(law.switches_stick_slip());
  // a value: p = sigma_0 gives tau = m k (1 - e^-1.25) (independently evaluated: 1 - e^-1.25 =
  // 0.7134952031398099)
  EXPECT_NEAR(law.shear_stress(sigma_0), m * k * 0.7134952031398099, 1e-12 * m * k);
  const SlipLimit at_sigma = law.slip_limit(sigma_0 * area, area);
  EXPECT_NEAR(at_sigma.value(sigma_0 * area), m * k * area * 0.7134952031398099, 1e-10);
  // p -> 0: tau / p -> 1.25 m k / sigma_0 = 1.25 m / sqrt(3) (relative error O(p / sigma_0))
  const double mu_0 = 1.25 * m / std::sqrt(3.);
  for (const double p : {1e-3, 1e-6})
    EXPECT_NEAR(law.shear_stress(p) / p, mu_0, 2. * mu_0 * 1.25 * p / sigma_0) << p;
  EXPECT_NEAR(law.slip_limit(1e-9 * area, area).slope, mu_0, 1e-9);
  EXPECT_EQ(law.slip_limit(0., area).value(0.), 0.);
  // tension: the tangent at 0, as Coulomb
  EXPECT_DOUBLE_EQ(law.slip_limit(-1., area).slope, mu_0);
  // p -> infinity: tau -> m k (exp(-1.25 * 40) ~ 2e-22 below it), slope -> 0
  EXPECT_NEAR(law.shear_stress(40. * sigma_0), m * k, 1e-12 * m * k);
  EXPECT_LT(law.slip_limit(40. * sigma_0 * area, area).slope, 1e-20);
  // monotone between the limits and always below both
  double previous = 0.;
  for (double p = 1.; p < 2000.; p *= 1.5)
  {
    const double tau = law.shear_stress(p);
    EXPECT_GT(tau, previous);
    EXPECT_LE(tau, std::min(mu_0 * p, m * k) * (1. + 1e-14));
    previous = tau;
  }
  // the affine piece is the tangent: its slope against central differences of T(R_n)
  for (const double p : {10., 300., 900.})
  {
    const double h = 1e-4, R = p * area;
    const double dT
        = (law.slip_limit(R + h, area).value(R + h) - law.slip_limit(R - h, area).value(R - h))
          / (2. * h);
    EXPECT_NEAR(law.slip_limit(R, area).slope, dT, 1e-8) << p;
  }
  // stick inside the limit, slip outside with the limit as force
  EXPECT_FALSE(law.respond(300. * area, 0.9 * law.shear_stress(300.) * area, area).slip);
  const FrictionResponse r = law.respond(300. * area, -1e6, area);
  EXPECT_TRUE(r.slip);
  EXPECT_NEAR(r.tangential, -law.shear_stress(300.) * area, 1e-10);
  expect_derivatives(law, 300. * area, 1e6, area);
  expect_derivatives(law, 50. * area, -1e6, area);
}
