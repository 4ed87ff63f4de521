/**
 * @file test_thermal_material.cc
 * Temperature-dependent properties (PropertyTable) and thermal strain around every kinematics
 * (ThermalExpansionModel) and the martensitic transformation (PhaseTransformationModel): closed
 * forms and finite-difference tangents.
 */
#include <ausroll/core/exceptions.h>
#include <ausroll/material/bainite_kinetics.h>
#include <ausroll/material/constitutive_model.h>
#include <ausroll/material/material_point.h>
#include <ausroll/material/phase_transformation_model.h>
#include <ausroll/material/property_table.h>
#include <ausroll/material/thermal_expansion_model.h>
#include <ausroll/material/transformation_plasticity.h>

#include "material_test_utilities.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

using namespace ausroll::material;
using dealii::Tensor;

namespace
{
  const KinematicsType all_kinematics[] = {KinematicsType::small_strain,
                                           KinematicsType::total_lagrangian,
                                           KinematicsType::updated_lagrangian,
                                           KinematicsType::finite_strain};

  MaterialParameters steel(const double H = 0.)
  {
    MaterialParameters p;
    p.youngs_modulus = 200000.;
    p.poissons_ratio = 0.3;
    p.yield_stress = 400.;
    p.hardening_modulus = H;
    return p;
  }

  Tensor<2, 3> identity()
  {
    return Tensor<2, 3>(dealii::unit_symmetric_tensor<3>());
  }

  ThermalExpansionParameters expansion(const double alpha, const double t_ref = 20.)
  {
    ThermalExpansionParameters t;
    t.expansion = PropertyTable(alpha);
    t.reference_temperature = t_ref;
    return t;
  }

  double max_abs(const Tensor<2, 3> &t)
  {
    double m = 0.;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        m = std::max(m, std::abs(t[i][j]));
    return m;
  }
} // namespace

// ------------------------------------------------------------------------------ PropertyTable

TEST(PropertyTable, ConstantTableAndFile)
{
  const PropertyTable c = PropertyTable::parse("45", "Thermal/Conductivity", "", true);
  EXPECT_TRUE(c.is_constant());
  EXPECT_EQ(c.value(-100.), 45.);
  EXPECT_EQ(c.value(1000.), 45.);
  EXPECT_EQ(c.derivative(300.), 0.);

  // linear between rows, constant beyond the ends (no extrapolation)
  const PropertyTable t
      = PropertyTable::parse("20: 45, 300: 40, 600: 34", "Thermal/Conductivity", "", true);
  EXPECT_FALSE(t.is_constant());
  EXPECT_DOUBLE_EQ(t.value(20.), 45.);
  EXPECT_DOUBLE_EQ(t.value(160.), 42.5);
  EXPECT_DOUBLE_EQ(t.value(450.), 37.);
  EXPECT_DOUBLE_EQ(t.value(0.), 45.);
  EXPECT_DOUBLE_EQ(t.value(900.), 34.);
  EXPECT_DOUBLE_EQ(t.derivative(100.), -5. / 280.);
  EXPECT_EQ(t.min_value(), 34.);
  EXPECT_EQ(t.max_value(), 45.);

  // the same table from a CSV file with a header, next to the .prm
  {
    std::ofstream f("property_table_test.csv");
    f << "temperature,conductivity\n20, 45\n300, 40\n600, 34\n";
  }
  const PropertyTable from_file
      = PropertyTable::parse("file: property_table_test.csv", "Thermal/Conductivity", ".", true);
  for (const double T : {0., 20., 160., 450., 900.})
    EXPECT_DOUBLE_EQ(from_file.value(T), t.value(T));
}

TEST(PropertyTable, BadTablesNameTheEntry)
{
  const auto message = [](const std::string &text, const bool positive)
  {
    try
    {
      PropertyTable::parse(text, "Thermal/Specific heat", ".", positive);
    }
    catch (const ausroll::InputError &e)
    {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("20: 1, 20: 2", true).find("must increase strictly"), std::string::npos);
  EXPECT_NE(message("300: 1, 20: 2", true).find("Thermal/Specific heat"), std::string::npos);
  EXPECT_NE(message("20: 1, 300: -2", true).find("must be positive"), std::string::npos);
  EXPECT_NE(message("", true).find("empty"), std::string::npos);
  EXPECT_NE(message("20 45", true).find("is not a number"), std::string::npos);
  EXPECT_NE(message("20: 45, 300", true).find("temperature: value"), std::string::npos);
  EXPECT_NE(message("file: no_such_table.csv", true).find("cannot open"), std::string::npos);
  EXPECT_NE(message("file: /dev/zero", true).find("not a regular file"), std::string::npos);
}

// ------------------------------------------------------------------------------ thermal strain

TEST(ThermalExpansionModel, FreeExpansionIsStressFreeInEveryKinematics)
{
  // A free body heated uniformly: F = theta I (multiplicative) or I + (theta - 1) I (additive),
  // which is the same tensor; P must vanish to round-off (relative to E alpha dT = 2400 MPa).
  const double                     alpha = 1.2e-5, T = 1020.; // dT = 1000 K: theta - 1 = 0.012
  const ThermalExpansionParameters thermal = expansion(alpha);
  for (const KinematicsType k : all_kinematics)
  {
    const auto    model = create_constitutive_model(k, steel(), false, &thermal);
    MaterialState old;
    old.temperature = T;
    MaterialState state;
    Tensor<2, 3>  P;
    model->evaluate((1. + alpha * 1000.) * identity(), old, state, P, nullptr);
    EXPECT_LT(max_abs(P), 1e-9 * 2400.) << to_string(k);
    EXPECT_EQ(state.temperature, T);
  }
}

TEST(ThermalExpansionModel, ClampedBlockClosedForms)
{
  // F = I (clamped in all directions): small strain sigma = -3 K alpha dT exactly; finite strain
  // (logarithmic elastic strain -ln(theta) per direction in the intermediate configuration):
  // Cauchy sigma = -3 K ln(theta) theta^3 (tau_mech = -3 K ln theta per intermediate volume).
  const double                     E = 200000., nu = 0.3, K = E / (3. * (1. - 2. * nu));
  const double                     alpha = 1.2e-5, dT = 100.;
  const double                     theta = 1. + alpha * dT;
  const ThermalExpansionParameters thermal = expansion(alpha);
  MaterialState                    old;
  old.temperature = 20. + dT;
  for (const auto &[k, expected] :
       {std::pair{KinematicsType::small_strain, -3. * K * alpha * dT},
        std::pair{KinematicsType::finite_strain, -3. * K * std::log(theta) * std::pow(theta, 3)}})
  {
    const auto    model = create_constitutive_model(k, steel(), false, &thermal);
    MaterialState state;
    Tensor<2, 3>  P;
    model->evaluate(identity(), old, state, P, nullptr);
    for (unsigned int i = 0; i < 3; ++i)
    {
      EXPECT_NEAR(state.stress[i][i], expected, 1e-10 * std::abs(expected)) << to_string(k);
      EXPECT_NEAR(P[i][i], expected, 1e-10 * std::abs(expected)) << to_string(k); // F = I
    }
    EXPECT_NEAR(state.stress[0][1], 0., 1e-12 * std::abs(expected));
  }
}

namespace
{
  /** dP/dF of every kinematics wrapped with thermal expansion against central differences of
      all nine components of F (h = 1e-7; the bound of the isothermal models, 1e-6 relative), at
      a plastic and an elastic F, at temperature @p T. */
  void expect_tangents_match(const MaterialParameters &material, const double T)
  {
    const Tensor<2, 3> F_plastic
        = identity() + Tensor<2, 3>({{0.03, 0.01, 0.}, {0.005, -0.02, 0.002}, {0., 0.003, -0.008}});
    const Tensor<2, 3> F_elastic
        = identity() + 1e-4 * Tensor<2, 3>({{3., 1., 0.}, {0.5, -2., 0.2}, {0., 0.3, -0.8}});
    const ThermalExpansionParameters thermal = expansion(1.2e-5);
    for (const KinematicsType k : all_kinematics)
    {
      const auto    model = create_constitutive_model(k, material, false, &thermal);
      MaterialState old;
      old.temperature = T;
      const double e_plastic = ausroll::testing::tangent_error(*model, old, F_plastic);
      const double e_elastic = ausroll::testing::tangent_error(*model, old, F_elastic);
      std::printf("[ %-18s ] T = %g: FD error plastic %.2e, elastic %.2e\n",
                  to_string(k).c_str(),
                  T,
                  e_plastic,
                  e_elastic);
      EXPECT_LT(e_plastic, 1e-6) << to_string(k);
      EXPECT_LT(e_elastic, 1e-6) << to_string(k);
    }
  }
} // namespace

TEST(ThermalExpansionModel, TangentsMatchFiniteDifferences)
{
  // At T far from T_ref. (PlaneStressDriver condenses F_zz out of its tangent and is checked
  // in test_finite_strain.cc; the wrapper sits inside it.)
  expect_tangents_match(steel(1000.), 320.);
}

TEST(ThermalExpansionModel, PlasticWorkOfLinearHardeningIsExact)
{
  // Small strain, uniaxial strain path, linear isotropic hardening: on the yield surface
  // sigma_vm = sigma_0 + H alpha, so the trapezoidal rule integrates int sigma_vm d alpha
  // exactly once the path is plastic: W(alpha_2) - W(alpha_1) = sigma_0 (alpha_2 - alpha_1)
  // + H (alpha_2^2 - alpha_1^2) / 2 to round-off, whatever the step sizes.
  const double                     H = 2000.;
  const ThermalExpansionParameters thermal = expansion(1.2e-5);
  const auto                       model
      = create_constitutive_model(KinematicsType::small_strain, steel(H), false, &thermal);
  MaterialPoint point;
  point.committed.temperature = point.trial.temperature = 20.;
  Tensor<2, 3>        P;
  std::vector<double> alpha, work;
  for (unsigned int s = 1; s <= 40; ++s)
  {
    Tensor<2, 3> F = identity();
    F[0][0] -= 0.0005 * s + 1e-5 * s * s; // uneven steps
    model->evaluate(F, point.committed, point.trial, P, nullptr);
    point.commit();
    alpha.push_back(point.committed.equivalent_plastic_strain);
    work.push_back(point.committed.plastic_work);
  }
  ASSERT_GT(alpha[5], 0.);
  ASSERT_GT(alpha.back(), 0.01);
  const double a1 = alpha[5], a2 = alpha.back();
  const double expected = 400. * (a2 - a1) + 0.5 * H * (a2 * a2 - a1 * a1);
  EXPECT_NEAR(work.back() - work[5], expected, 1e-10 * expected);
}

// ------------------------------------------------------- temperature-dependent moduli and yield

namespace
{
  /** Steel with E, nu, sigma_0 and H as tables in T (values at 170 C: E = 175000, nu = 0.31,
      sigma_0 = 300, H = 1500). */
  MaterialParameters hot_steel()
  {
    MaterialParameters p;
    p.youngs_modulus = PropertyTable::parse("20: 200000, 320: 150000", "E", "", true);
    p.poissons_ratio = PropertyTable::parse("20: 0.3, 320: 0.32", "nu", "", false);
    p.yield_stress = PropertyTable::parse("20: 400, 320: 200", "sigma_0", "", true);
    p.hardening_modulus = PropertyTable::parse("20: 2000, 320: 1000", "H", "", false, true);
    return p;
  }
} // namespace

TEST(TemperatureDependentMaterial, ModuliAndYieldStressAtTheStateTemperature)
{
  // Clamped (F = I) at T = 170 C: small strain sigma = -3 K(T) alpha dT with the moduli of the
  // table at 170 C (E = 175000, nu = 0.31), to round-off; and a radial return at 170 C ends on
  // sigma_0(T) + H(T) dalpha (J2, linear hardening), to 1e-12.
  const double                     E = 175000., nu = 0.31, K = E / (3. * (1. - 2. * nu));
  const double                     alpha = 1.2e-5, dT = 150.;
  const ThermalExpansionParameters thermal = expansion(alpha);
  const MaterialParameters         material = hot_steel();
  EXPECT_EQ(material.first_temperature_dependent_entry(), "Material/Young's modulus");
  EXPECT_TRUE(material.depends_on_temperature());
  EXPECT_FALSE(steel().depends_on_temperature());
  {
    const auto model
        = create_constitutive_model(KinematicsType::small_strain, material, false, &thermal);
    MaterialState old, state;
    old.temperature = 20. + dT;
    Tensor<2, 3> P;
    model->evaluate(identity(), old, state, P, nullptr);
    const double expected = -3. * K * alpha * dT; // 222 MPa hydrostatic: no yielding
    for (unsigned int i = 0; i < 3; ++i)
      EXPECT_NEAR(state.stress[i][i], expected, 1e-12 * std::abs(expected));
    // the same state at 20 C uses E = 200000, nu = 0.3 (no thermal strain there)
    EXPECT_NEAR(model->plasticity().elasticity(20.).youngs_modulus, 200000., 1e-9);
    EXPECT_NEAR(model->plasticity().elasticity(170.).poissons_ratio, nu, 1e-15);
  }
  const auto                    plasticity = create_plasticity_model(material);
  dealii::SymmetricTensor<2, 3> trial;
  trial[0][1] = trial[1][0] = 600.; // q_trial = sqrt(3) 600 = 1039 MPa
  const ReturnMappingResult r = plasticity->return_map(trial, {}, 0.01, 170.);
  ASSERT_TRUE(r.plastic);
  const double q = std::sqrt(1.5) * dealii::deviator(r.stress).norm();
  EXPECT_NEAR(q, 300. + 1500. * (0.01 + r.eq_plastic_strain_increment), 1e-12 * q);
  EXPECT_NEAR(plasticity->yield_function(
                  r.stress, r.back_stress, 0.01 + r.eq_plastic_strain_increment, 170.),
              0.,
              1e-9);
  // at 20 C the same stress lies inside the surface of sigma_0 (20) + H (20) 0.01 = 420 MPa
  EXPECT_NEAR(plasticity->yield_function(r.stress, r.back_stress, 0.01, 20.), q - 420., 1e-9);
}

TEST(TemperatureDependentMaterial, TangentsMatchFiniteDifferences)
{
  // The moduli and hardening of the tables at 170 C (between the rows): the temperature is
  // fixed during the mechanical solve, so the tangent is the isothermal one at T.
  expect_tangents_match(hot_steel(), 170.);
}

// ------------------------------------------------------------------ martensitic transformation

namespace
{
  PhaseParameters phases()
  {
    PhaseParameters p;
    p.enabled = true;
    return p; // Andrews' Ms of AISI 9310, b = 0.011, dV/V = 4.64 - 0.53 C per cent
  }
} // namespace

TEST(PhaseTransformationModel, KoistinenMarburgerIrreversibleAndAndrewsMs)
{
  // Ms(0.8 wt% C) by Andrews with 0.55 Mn, 3.25 Ni, 1.2 Cr, 0.12 Mo; the fraction follows
  // 1 - exp(-b (Ms - T)) below Ms, is 0 above, never decreases on reheating.
  const PhaseParameters            p = phases();
  const ThermalExpansionParameters thermal = expansion(0.);
  const PhaseTransformationModel   model(
      create_constitutive_model(KinematicsType::small_strain, steel(), false, &thermal), p);
  const double ms = 539. - 423. * 0.8 - 30.4 * 0.55 - 17.7 * 3.25 - 12.1 * 1.2 - 7.5 * 0.12;
  EXPECT_NEAR(model.martensite_start(0.8), ms, 1e-12);
  EXPECT_EQ(model.martensite_fraction(0., 0.8, ms + 1.), 0.);
  const double f20 = 1. - std::exp(-0.011 * (ms - 20.));
  EXPECT_NEAR(model.martensite_fraction(0., 0.8, 20.), f20, 1e-14);
  EXPECT_EQ(model.martensite_fraction(f20, 0.8, 100.), f20); // reheated: no reversal
  EXPECT_EQ(model.martensite_fraction(f20, 0.8, 400.), f20); // above Ms: kept
  EXPECT_NEAR(model.transformation_stretch(1., 0.8), std::cbrt(1. + (4.64 - 0.424) / 100.), 1e-14);
  EXPECT_EQ(model.transformation_stretch(0., 0.8), 1.);
  // the quenched reference (Initial state = quenched): the stretch counts from f_0
  const double dv = (4.64 - 0.424) / 100.;
  EXPECT_NEAR(model.transformation_stretch(0.9, 0.8, 0., 0.3),
              std::cbrt((1. + 0.9 * dv) / (1. + 0.3 * dv)),
              1e-14);
  EXPECT_EQ(model.transformation_stretch(0.3, 0.8, 0., 0.3), 1.);
  // a transferred state that overshot is brought back: fractions in [0, 1], f_0 <= f, C >= 0
  MaterialState overshot;
  overshot.martensite = -0.1;
  overshot.initial_martensite = 0.05;
  overshot.bainite = 1.2;
  overshot.carbon = -0.01;
  model.make_admissible(overshot);
  EXPECT_EQ(overshot.martensite, 0.);
  EXPECT_EQ(overshot.initial_martensite, 0.);
  EXPECT_EQ(overshot.bainite, 1.);
  EXPECT_EQ(overshot.carbon, 0.);
  overshot.martensite = 1.3;
  model.make_admissible(overshot);
  EXPECT_EQ(overshot.martensite, 1.);
  EXPECT_EQ(overshot.bainite, 0.);
}

TEST(PhaseTransformationModel, FreeTransformationIsStressFreeAndTangentsMatch)
{
  // A free body below Ms expands by theta_th theta_tr (multiplicative) or alpha dT + theta_tr - 1
  // (small strain) and is stress-free (relative to E (theta - 1) ~ 2e3 MPa); dP/dF against central
  // differences (1e-6 relative, as the isothermal models) elastic and plastic.
  const PhaseParameters            p = phases();
  const ThermalExpansionParameters thermal = expansion(1.2e-5);
  const Tensor<2, 3>               F_plastic
      = identity() + Tensor<2, 3>({{0.03, 0.01, 0.}, {0.005, -0.02, 0.002}, {0., 0.003, -0.008}});
  for (const KinematicsType k : all_kinematics)
  {
    const auto    model = create_constitutive_model(k, steel(1000.), false, &thermal, &p);
    MaterialState old;
    old.temperature = 60.;
    old.carbon = 0.8;
    const auto   &pt = dynamic_cast<const PhaseTransformationModel &>(*model);
    const double  f = pt.martensite_fraction(0., 0.8, 60.);
    const double  th = 1. + 1.2e-5 * 40., tr = pt.transformation_stretch(f, 0.8);
    const double  stretch = k == KinematicsType::small_strain ? th + tr - 1. : th * tr;
    MaterialState state;
    Tensor<2, 3>  P;
    model->evaluate(stretch * identity(), old, state, P, nullptr);
    EXPECT_GT(f, 0.4) << to_string(k);
    EXPECT_NEAR(state.martensite, f, 1e-15) << to_string(k);
    EXPECT_LT(max_abs(P), 1e-9 * 2000.) << to_string(k);
    EXPECT_LT(ausroll::testing::tangent_error(*model, old, F_plastic), 1e-6) << to_string(k);
  }
}

// ------------------------------------------------------------------------ bainite (JMAK, TTT)

TEST(BainiteKinetics, IsothermalHoldIsJmakThroughTheTttTimes)
{
  // TTT rows 250 C: 20 / 400 s, 350 C: 10 / 200 s -> at 300 C t_s = 15 s, t_f = 300 s; JMAK
  // through (t_s, 1 %) and (t_f, 99 %): the fractions at t_s and t_f to 1e-12, and the
  // additivity rule is exact for an isothermal hold whatever the steps (uneven steps here).
  const BainiteKinetics b("250: 20, 350: 10", "250: 400, 350: 200", "start", "finish", "");
  ASSERT_TRUE(b.active());
  const double n = std::log(std::log(0.01) / std::log(0.99)) / std::log(20.);
  EXPECT_NEAR(b.exponent(300.), n, 1e-14);
  const double k = -std::log(0.99) / std::pow(15., n);
  EXPECT_NEAR(b.rate(300.), k, 1e-14 * k);
  EXPECT_NEAR(b.advance(0., 300., 15.), 0.01, 1e-12);
  EXPECT_NEAR(b.advance(0., 300., 300.), 0.99, 1e-12);
  double xi = 0., t = 0.;
  for (unsigned int s = 1; s <= 25; ++s)
  {
    const double dt = 0.5 * s;
    xi = b.advance(xi, 300., dt);
    t += dt;
    EXPECT_NEAR(xi, -std::expm1(-k * std::pow(t, n)), 1e-12) << "t = " << t;
  }
  // outside the range (below 250 C or above 350 C) nothing forms
  EXPECT_EQ(b.advance(0.2, 240., 100.), 0.2);
  EXPECT_EQ(b.advance(0.2, 360., 100.), 0.2);
}

TEST(BainiteKinetics, AdditivityAcrossTemperatures)
{
  // 10 s at 250 C, then 10 s at 350 C: the second hold starts at the fictitious time at which
  // 350 C gives the fraction of the first: t* = (-ln(1 - xi_1) / k_2)^(1/n_2).
  const BainiteKinetics b("250: 20, 350: 10", "250: 400, 350: 200", "start", "finish", "");
  const double          xi1 = -std::expm1(-b.rate(250.) * std::pow(10., b.exponent(250.)));
  EXPECT_NEAR(b.advance(0., 250., 10.), xi1, 1e-15);
  const double t_star = std::pow(-std::log1p(-xi1) / b.rate(350.), 1. / b.exponent(350.));
  EXPECT_NEAR(b.advance(xi1, 350., 10.),
              -std::expm1(-b.rate(350.) * std::pow(t_star + 10., b.exponent(350.))),
              1e-15);
  // two steps of 5 s at 350 C are one of 10 s
  EXPECT_NEAR(b.advance(b.advance(xi1, 350., 5.), 350., 5.), b.advance(xi1, 350., 10.), 1e-14);
}

TEST(BainiteKinetics, BadTablesNameTheEntry)
{
  const auto message = [](const std::string &start, const std::string &finish)
  {
    try
    {
      BainiteKinetics(
          start, finish, "Phases/Bainite start times", "Phases/Bainite finish times", "");
    }
    catch (const ausroll::InputError &e)
    {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message("", "").find("no error"), 0u);
  EXPECT_NE(message("250: 20, 350: 10", "").find("Phases/Bainite finish times: is empty"),
            std::string::npos);
  EXPECT_NE(message("350: 10, 250: 20", "250: 400, 350: 200").find("must increase strictly"),
            std::string::npos);
  EXPECT_NE(message("250: 20, 350: 10", "250: 400, 300: 200").find("same temperatures"),
            std::string::npos);
  EXPECT_NE(message("250: 20, 350: 10", "250: 400, 350: 5").find("later than the start"),
            std::string::npos);
}

// ------------------------------------------- TRIP and the mixture rule of the yield stress

namespace
{
  /** Phases with TRIP (K in 1/MPa) and, if @p mixture, martensite and bainite yield stresses. */
  PhaseParameters trip_phases(const double K, const bool mixture)
  {
    PhaseParameters p = phases();
    p.mechanics.trip_coefficient = K;
    if (mixture)
    {
      p.mechanics.martensite_yield_stress
          = PropertyTable::parse("20: 1400, 300: 1100", "m", "", true);
      p.mechanics.martensite_yield_given = true;
      p.mechanics.bainite_yield_stress = PropertyTable(800.);
      p.mechanics.bainite_yield_given = true;
    }
    return p;
  }

  /** A deviatoric back stress (MPa). */
  dealii::SymmetricTensor<2, 3> some_back_stress()
  {
    dealii::SymmetricTensor<2, 3> beta;
    beta[0][0] = 30.;
    beta[1][1] = -10.;
    beta[2][2] = -20.;
    beta[0][1] = 15.;
    return beta;
  }

  /** A deformation gradient that yields the steels of the tangent tests (3 % strain). */
  Tensor<2, 3> plastic_gradient()
  {
    return identity()
           + Tensor<2, 3>({{0.03, 0.01, 0.}, {0.005, -0.02, 0.002}, {0., 0.003, -0.008}});
  }

  /** A deformation gradient that stays elastic (3e-4 strain). */
  Tensor<2, 3> elastic_gradient()
  {
    return identity() + 1e-4 * Tensor<2, 3>({{3., 1., 0.}, {0.5, -2., 0.2}, {0., 0.3, -0.8}});
  }

  /** A deviatoric-plus-pressure stress (MPa). */
  dealii::SymmetricTensor<2, 3> some_stress(const double scale)
  {
    dealii::SymmetricTensor<2, 3> s;
    s[0][0] = 1.0 * scale;
    s[1][1] = -0.4 * scale;
    s[2][2] = 0.1 * scale;
    s[0][1] = 0.3 * scale;
    s[1][2] = -0.2 * scale;
    return s;
  }
} // namespace

TEST(TransformationPlasticity, LeblondPhiAndTripCompliance)
{
  // phi(z) = z (1 - ln z): 0 at 0, 1 at 1, increasing; kappa = 3/2 K (phi(z) - phi(z_old)) of
  // the product fraction z = f_M + f_B, 0 when nothing forms.
  EXPECT_EQ(TransformationPlasticity::leblond_phi(0.), 0.);
  EXPECT_NEAR(TransformationPlasticity::leblond_phi(1.), 1., 1e-15);
  EXPECT_NEAR(TransformationPlasticity::leblond_phi(0.5), 0.5 * (1. + std::log(2.)), 1e-15);
  TransformationPlasticityParameters p;
  p.trip_coefficient = 1e-4;
  const TransformationPlasticity trip(p);
  const PhaseStep                step{0.1, 0.2, 0.4, 0.25};
  EXPECT_NEAR(trip.trip_compliance(step),
              1.5e-4
                  * (TransformationPlasticity::leblond_phi(0.65)
                     - TransformationPlasticity::leblond_phi(0.3)),
              1e-18);
  EXPECT_EQ(trip.trip_compliance(PhaseStep{0.4, 0.25, 0.4, 0.25}), 0.);
  // no mixture entries: the austenite's law for every phase
  EXPECT_EQ(trip.austenite_weight(step), 1.);
  EXPECT_EQ(trip.product_yield_stress(step, 20.), 0.);
}

TEST(TransformationPlasticity, ReturnMapSatisfiesItsEquations)
{
  // The discrete equations, checked on the result (not on the closed form the code uses):
  // sigma = sigma_trial - 2 mu (Delta eps_p + Delta eps_tp), Delta eps_tp = kappa dev(sigma),
  // Delta eps_p = sqrt(3/2) dgamma n (so dgamma = sqrt(2/3) |Delta eps_p|) along dev(sigma) - beta,
  // beta = beta_old + 2/3 H_k Delta eps_p, and on yield sqrt(3/2) |dev sigma - beta| = w
  // sigma_y,A(alpha + dgamma) + f_M sigma_y,M(T) + f_B sigma_y,B(T). Elastic (TRIP only) and
  // plastic, with a back stress.
  MaterialParameters material = steel(1000.);
  material.kinematic_hardening_modulus = 5000.;
  const PhaseParameters p = trip_phases(1e-4, true);
  const auto            model = create_plasticity_model(material, &p.mechanics);
  const double          mu = 200000. / 2.6, T = 150.;
  const PhaseStep       step{0.1, 0.05, 0.3, 0.1};
  const double          kappa = 1.5e-4
                       * (TransformationPlasticity::leblond_phi(0.4)
                          - TransformationPlasticity::leblond_phi(0.15));
  const double sigma_y
      = 0.6 * (400. + 1000. * 0.02) + 0.3 * (1400. - 300. * 130. / 280.) + 0.1 * 800.;
  dealii::SymmetricTensor<2, 3> beta_old;
  beta_old[0][0] = 20.;
  beta_old[1][1] = -20.;
  beta_old[0][2] = 10.;
  for (const double scale : {100., 20000.})
  {
    const dealii::SymmetricTensor<2, 3> trial
        = some_stress(scale) + 50. * dealii::unit_symmetric_tensor<3>();
    const ReturnMappingResult           r = model->return_map(trial, beta_old, 0.02, T, step);
    const dealii::SymmetricTensor<2, 3> s = dealii::deviator(r.stress);
    const dealii::SymmetricTensor<2, 3> d_tp = kappa * s;
    const dealii::SymmetricTensor<2, 3> d_p = r.plastic_strain_increment - d_tp;
    EXPECT_LT((r.stress - (trial - 2. * mu * r.plastic_strain_increment)).norm(), 1e-9 * scale);
    EXPECT_LT((r.back_stress - beta_old - 2. / 3. * 5000. * d_p).norm(), 1e-9 * scale);
    EXPECT_NEAR(std::sqrt(2. / 3.) * d_p.norm(), r.eq_plastic_strain_increment, 1e-12);
    EXPECT_TRUE(r.trip);
    if (scale < 1000.)
      EXPECT_FALSE(r.plastic);
    else
    {
      EXPECT_TRUE(r.plastic);
      const dealii::SymmetricTensor<2, 3> eta = s - r.back_stress;
      EXPECT_LT((d_p / d_p.norm() - eta / eta.norm()).norm(), 1e-12);
      EXPECT_NEAR(std::sqrt(1.5) * eta.norm(),
                  sigma_y + 0.6 * 1000. * r.eq_plastic_strain_increment,
                  1e-9 * sigma_y);
      EXPECT_NEAR(model->yield_function(r.stress,
                                        r.back_stress,
                                        0.02 + r.eq_plastic_strain_increment,
                                        T,
                                        PhaseStep{0.3, 0.1, 0.3, 0.1}),
                  0.,
                  1e-9 * sigma_y);
    }
  }
}

TEST(TransformationPlasticity, TangentsMatchFiniteDifferences)
{
  // dP/dF with TRIP (K = 2e-5 1/MPa: small enough that the 3 % strain still yields) and the
  // mixture rule around every kinematics, against
  // central differences (1e-6 relative, as the isothermal models): a plastic and an elastic F
  // while martensite forms (f_M from 0 or from 0.2 to about 0.45 at 60 C), with and without a
  // rotated back stress (H_k > 0: the back-stress sensitivity of the updated Lagrangian and
  // finite-strain models), and with TRIP alone.
  const ThermalExpansionParameters thermal = expansion(1.2e-5);
  const Tensor<2, 3>               F_plastic = plastic_gradient();
  const Tensor<2, 3>               F_elastic = elastic_gradient();
  MaterialParameters               kinematic = steel(1000.);
  kinematic.kinematic_hardening_modulus = 5000.;
  for (const bool mixture : {true, false})
    for (const double f_old : {0., 0.2})
      for (const bool back : {false, true})
        for (const KinematicsType k : all_kinematics)
        {
          const PhaseParameters p = trip_phases(2e-5, mixture);
          const auto            model
              = create_constitutive_model(k, back ? kinematic : steel(1000.), false, &thermal, &p);
          MaterialState old;
          old.temperature = 60.;
          old.carbon = 0.8;
          old.martensite = f_old;
          old.equivalent_plastic_strain = 0.01;
          if (back)
          {
            old.back_stress = some_back_stress();
          }
          MaterialState state;
          Tensor<2, 3>  P;
          model->evaluate(F_plastic, old, state, P, nullptr);
          EXPECT_GT(state.martensite, f_old + 0.15);
          EXPECT_GT(state.equivalent_plastic_strain, 0.01) << to_string(k);
          const double e_plastic = ausroll::testing::tangent_error(*model, old, F_plastic);
          const double e_elastic = ausroll::testing::tangent_error(*model, old, F_elastic);
          std::printf("[ %-18s ] mixture %d, f_old %.1f, back stress %d: FD error plastic %.2e, "
                      "elastic %.2e\n",
                      to_string(k).c_str(),
                      mixture,
                      f_old,
                      back,
                      e_plastic,
                      e_elastic);
          EXPECT_LT(e_plastic, 1e-6) << to_string(k);
          EXPECT_LT(e_elastic, 1e-6) << to_string(k);
        }
}

TEST(TransformationPlasticity, PlaneStressTangentsMatchFiniteDifferences)
{
  // The PlaneStressDriver around the phase model (TRIP, mixture, back stress) condenses F_zz out
  // of the tangent: the in-plane dP/dF against central differences of the in-plane F (as
  // test_finite_strain.cc checks the driver), 1e-6 as above.
  const ThermalExpansionParameters thermal = expansion(1.2e-5);
  const PhaseParameters            p = trip_phases(2e-5, true);
  MaterialParameters               kinematic = steel(1000.);
  kinematic.kinematic_hardening_modulus = 5000.;
  const Tensor<2, 3> F_plastic
      = identity() + Tensor<2, 3>({{0.03, 0.01, 0.}, {0.005, -0.02, 0.}, {0., 0., 0.}});
  for (const KinematicsType k : all_kinematics)
  {
    const auto    model = create_constitutive_model(k, kinematic, true, &thermal, &p);
    MaterialState old;
    old.temperature = 60.;
    old.carbon = 0.8;
    old.back_stress = some_back_stress();
    MaterialState state;
    Tensor<2, 3>  P;
    model->evaluate(F_plastic, old, state, P, nullptr);
    EXPECT_GT(state.equivalent_plastic_strain, 0.) << to_string(k);
    EXPECT_LT(std::abs(P[2][2]), 1e-9 * 400.) << to_string(k);
    const double error = ausroll::testing::in_plane_tangent_error(*model, old, F_plastic);
    std::printf("[ %-18s ] plane stress: FD error %.2e\n", to_string(k).c_str(), error);
    EXPECT_LT(error, 1e-6) << to_string(k);
  }
}

TEST(TransformationPlasticity, DefaultsLeaveTheReturnMapUnchanged)
{
  // K = 0 and no mixture entries: the phase model gives the stress and tangent of the model
  // without TRIP to the last bit (the return map without phases runs).
  const ThermalExpansionParameters thermal = expansion(1.2e-5);
  const PhaseParameters            off = phases();
  ASSERT_FALSE(off.mechanics.active());
  const Tensor<2, 3> F
      = identity() + Tensor<2, 3>({{0.03, 0.01, 0.}, {0.005, -0.02, 0.002}, {0., 0.003, -0.008}});
  for (const KinematicsType k : all_kinematics)
  {
    const auto    model = create_constitutive_model(k, steel(1000.), false, &thermal, &off);
    MaterialState old;
    old.temperature = 60.;
    old.carbon = 0.8;
    MaterialState a, b;
    Tensor<2, 3>  Pa, Pb;
    Tensor<4, 3>  Aa, Ab;
    model->evaluate(F, old, a, Pa, &Aa);
    PhaseParameters zero = phases();
    zero.mechanics.trip_coefficient = 0.;
    const auto same = create_constitutive_model(k, steel(1000.), false, &thermal, &zero);
    same->evaluate(F, old, b, Pb, &Ab);
    EXPECT_EQ(Pa, Pb) << to_string(k);
    EXPECT_EQ(Aa, Ab) << to_string(k);
  }
}

TEST(TransformationPlasticity, BadEntriesNameTheEntry)
{
  const auto message = [](const std::string &K, const std::string &martensite)
  {
    dealii::ParameterHandler prm;
    prm.enter_subsection("Phases");
    TransformationPlasticityParameters::declare_parameters(prm);
    prm.set("TRIP coefficient", K);
    prm.set("Martensite yield stress", martensite);
    TransformationPlasticityParameters p;
    try
    {
      p.parse_parameters(prm, "");
    }
    catch (const ausroll::InputError &e)
    {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message("1e-4", "20: 1400, 300: 1100"), "no error");
  EXPECT_NE(message("-1e-5", "").find("Phases/TRIP coefficient: must not be negative"),
            std::string::npos);
  EXPECT_NE(message("0", "300: 1100, 20: 1400").find("Phases/Martensite yield stress"),
            std::string::npos);
}

TEST(TransformationPlasticity, ElasticMaterialRelaxesByTrip)
{
  // Yield criterion none: TRIP alone, dev sigma = 2 mu dev eps / c with c = 1 + 2 mu kappa,
  // kappa = 3/2 K phi(f) (small strain; the transformation strain is volumetric, so dev eps is
  // the total one), to round-off; dP/dF of all four kinematics against central differences.
  MaterialParameters elastic = steel();
  elastic.yield_criterion = YieldCriterion::none;
  const ThermalExpansionParameters thermal = expansion(0.);
  const PhaseParameters            p = trip_phases(1e-4, false);
  const Tensor<2, 3>               strain({{0.002, 0.001, 0.}, {0.001, -0.001, 0.}, {0., 0., 0.}});
  for (const KinematicsType k : all_kinematics)
  {
    const auto    model = create_constitutive_model(k, elastic, false, &thermal, &p);
    MaterialState old;
    old.temperature = 60.;
    old.carbon = 0.8;
    if (k == KinematicsType::small_strain)
    {
      MaterialState state;
      Tensor<2, 3>  P;
      model->evaluate(identity() + strain, old, state, P, nullptr);
      const double mu = 200000. / 2.6;
      const double c
          = 1. + 2. * mu * 1.5e-4 * TransformationPlasticity::leblond_phi(state.martensite);
      const dealii::SymmetricTensor<2, 3> expected
          = 2. * mu / c * dealii::deviator(dealii::symmetrize(strain));
      EXPECT_GT(c, 10.);
      EXPECT_LT((dealii::deviator(state.stress) - expected).norm(), 1e-12 * expected.norm());
    }
    EXPECT_LT(ausroll::testing::tangent_error(*model, old, identity() + strain), 1e-6)
        << to_string(k);
  }
}

// ------------------------------------ the yield stress and hardening of martensite in C and T

namespace
{
  /** The `Phases` mechanics of the entries @p yield and @p hardening (parsed, as the `.prm`). */
  TransformationPlasticityParameters
  carbon_mechanics(const std::string &yield, const std::string &hardening, const double K = 0.)
  {
    dealii::ParameterHandler prm;
    prm.enter_subsection("Phases");
    TransformationPlasticityParameters::declare_parameters(prm);
    prm.set("TRIP coefficient", K);
    prm.set("Martensite yield stress", yield);
    prm.set("Martensite hardening modulus", hardening);
    TransformationPlasticityParameters p;
    p.parse_parameters(prm, "");
    return p;
  }

  /** Krauss' fit and a hardening modulus in C and T (MPa). */
  double krauss(const double C)
  {
    return 413. + 1720. * std::sqrt(C);
  }
  double martensite_modulus(const double C, const double T)
  {
    return 2000. + 1000. * C - 2. * T;
  }
} // namespace

TEST(TransformationPlasticity, MartensiteYieldStressAndHardeningOfCarbon)
{
  // The entries as expressions of C and T are evaluated at the point's carbon content (PhaseStep
  // carries it): the products' yield stress f_M sigma_y,M(C, T) and hardening f_M H_M(C, T) to
  // round-off; a number or table (no C) gives the same at every C.
  const TransformationPlasticity mixture(
      carbon_mechanics("413 + 1720*sqrt(C)", "2000 + 1000*C - 2*T"));
  ASSERT_TRUE(mixture.products_harden());
  for (const double C : {0.2, 0.8})
  {
    const PhaseStep step{0.1, 0., 0.6, 0., C};
    EXPECT_NEAR(mixture.product_yield_stress(step, 150.), 0.6 * krauss(C), 1e-12 * krauss(C));
    EXPECT_NEAR(mixture.product_hardening(step, 150.),
                0.6 * martensite_modulus(C, 150.),
                1e-12 * martensite_modulus(C, 150.));
    EXPECT_EQ(mixture.austenite_weight(step), 0.4);
  }
  const TransformationPlasticity table(carbon_mechanics("20: 1400, 300: 1100", ""));
  EXPECT_FALSE(table.products_harden());
  EXPECT_EQ(table.product_hardening(PhaseStep{0., 0., 1., 0., 0.8}, 20.), 0.);
  EXPECT_EQ(table.product_yield_stress(PhaseStep{0., 0., 1., 0., 0.2}, 160.),
            table.product_yield_stress(PhaseStep{0., 0., 1., 0., 0.8}, 160.));
  EXPECT_NEAR(table.product_yield_stress(PhaseStep{0., 0., 1., 0., 0.2}, 160.), 1250., 1e-12);
}

TEST(TransformationPlasticity, HardeningMartensiteReturnMapSatisfiesItsEquations)
{
  // Pure martensite (f_M = 1 before and after: no TRIP) at C = 0.2 and 0.8: the radial return
  // with sigma_y = sigma_y,M(C, T) + H_M(C, T) alpha: on yield sqrt(3/2) |dev sigma| = that at
  // alpha_old + dgamma, and the uniaxial closed form dgamma = (q_trial - sigma_y(alpha_old)) /
  // (3 mu + H_M), to 1e-9 relative.
  const auto mixture
      = carbon_mechanics("413 + 1720*sqrt(C)", "2000 + 1000*C - 2*T"); // keeps the tables alive
  const auto   transforming = create_plasticity_model(steel(1000.), &mixture);
  const double mu = 200000. / 2.6, T = 60., alpha_old = 0.01;
  for (const double C : {0.2, 0.8})
  {
    const PhaseStep               step{1., 0., 1., 0., C};
    dealii::SymmetricTensor<2, 3> trial;
    trial[0][0] = 6000.; // uniaxial: q_trial = 6000
    const ReturnMappingResult r = transforming->return_map(trial, {}, alpha_old, T, step);
    ASSERT_TRUE(r.plastic);
    const double H = martensite_modulus(C, T);
    const double q_trial = 6000.;
    const double dgamma = (q_trial - krauss(C) - H * alpha_old) / (3. * mu + H);
    EXPECT_NEAR(r.eq_plastic_strain_increment, dgamma, 1e-9 * dgamma) << "C = " << C;
    EXPECT_NEAR(std::sqrt(1.5) * dealii::deviator(r.stress).norm(),
                krauss(C) + H * (alpha_old + dgamma),
                1e-9 * krauss(C))
        << "C = " << C;
    EXPECT_NEAR(transforming->yield_function(
                    r.stress, r.back_stress, alpha_old + r.eq_plastic_strain_increment, T, step),
                0.,
                1e-9 * krauss(C));
  }
}

TEST(TransformationPlasticity, CarbonDependentTangentsMatchFiniteDifferences)
{
  // dP/dF with the martensite yield stress and hardening modulus as expressions of C and T,
  // while martensite forms (f_M from 0.2 to about 0.45 at 60 C) with TRIP, at C = 0.2 and 0.8,
  // around every kinematics: against central differences (1e-6 relative), plastic and elastic.
  const ThermalExpansionParameters thermal = expansion(1.2e-5);
  const Tensor<2, 3>               F_plastic = plastic_gradient();
  const Tensor<2, 3>               F_elastic = elastic_gradient();
  PhaseParameters                  p = phases();
  p.mechanics = carbon_mechanics("413 + 1720*sqrt(C)", "2000 + 1000*C - 2*T", 2e-5);
  for (const double C : {0.2, 0.8})
    for (const KinematicsType k : all_kinematics)
    {
      const auto    model = create_constitutive_model(k, steel(1000.), false, &thermal, &p);
      MaterialState old;
      old.temperature = C < 0.5 ? 300. : 60.; // below Ms of either carbon content
      old.carbon = C;
      old.martensite = 0.2;
      old.equivalent_plastic_strain = 0.01;
      MaterialState state;
      Tensor<2, 3>  P;
      model->evaluate(F_plastic, old, state, P, nullptr);
      EXPECT_GT(state.martensite, 0.35) << to_string(k);
      EXPECT_GT(state.equivalent_plastic_strain, 0.01) << to_string(k);
      const double e_plastic = ausroll::testing::tangent_error(*model, old, F_plastic);
      const double e_elastic = ausroll::testing::tangent_error(*model, old, F_elastic);
      std::printf("[ %-18s ] C %.1f: FD error plastic %.2e, elastic %.2e\n",
                  to_string(k).c_str(),
                  C,
                  e_plastic,
                  e_elastic);
      EXPECT_LT(e_plastic, 1e-6) << to_string(k);
      EXPECT_LT(e_elastic, 1e-6) << to_string(k);
    }
}

TEST(TransformationPlasticity, BadCarbonExpressionsNameTheEntry)
{
  const auto message = [](const std::string &yield, const std::string &hardening)
  {
    try
    {
      carbon_mechanics(yield, hardening);
    }
    catch (const ausroll::InputError &e)
    {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message("413 + 1720*sqrt(C)", "1000*C"), "no error");
  EXPECT_NE(message("413 - 1720*C", "").find("Phases/Martensite yield stress: '413 - 1720*C' is"),
            std::string::npos);
  EXPECT_NE(message("413 + 1720*sqrt(X)", "").find("cannot parse"), std::string::npos);
  EXPECT_NE(message("1400", "-1000*C").find("Phases/Martensite hardening modulus"),
            std::string::npos);
  EXPECT_NE(message("", "1000").find("Phases/Martensite hardening modulus: hardens the"),
            std::string::npos);
}

TEST(PhaseTransformationModel, MechanicalStabilisationLowersMs)
{
  // Ms(C, alpha) = Ms(C) - G_0 / S (sqrt(1 + alpha / eps_0) - 1) with the option (defaults of
  // MUCG46: G_0 = 35.11 J/mol, eps_0 = 0.1, S = 6.94 J/(mol K)), Ms(C) without it at any alpha;
  // the KM fraction follows the shifted Ms.
  const ThermalExpansionParameters thermal = expansion(0.);
  PhaseParameters                  p = phases();
  const PhaseTransformationModel   plain(
      create_constitutive_model(KinematicsType::small_strain, steel(), false, &thermal), p);
  p.mechanical_stabilisation = true;
  const PhaseTransformationModel stabilised(
      create_constitutive_model(KinematicsType::small_strain, steel(), false, &thermal), p);
  const double ms = 539. - 423. * 0.8 - 30.4 * 0.55 - 17.7 * 3.25 - 12.1 * 1.2 - 7.5 * 0.12;
  EXPECT_EQ(plain.martensite_start(0.8, 0.3), plain.martensite_start(0.8));
  EXPECT_EQ(stabilised.martensite_start(0.8, 0.), plain.martensite_start(0.8));
  const double shift = 35.11 / 6.94 * (std::sqrt(1. + 0.3 / 0.1) - 1.);
  EXPECT_NEAR(stabilised.martensite_start(0.8, 0.3), ms - shift, 1e-12);
  EXPECT_NEAR(shift, 5.06, 0.01);
  EXPECT_NEAR(stabilised.martensite_fraction(0., 0.8, 20., 0., 0.3),
              1. - std::exp(-0.011 * (ms - shift - 20.)),
              1e-14);
}
