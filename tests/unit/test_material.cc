// Unit tests of the material points: von Mises return mapping against closed-form solutions and
// consistent tangents against finite differences.
#include <ausroll/core/exceptions.h>
#include <ausroll/material/constitutive_model.h>
#include <ausroll/material/material_point.h>
#include <ausroll/material/plasticity_model.h>
#include <ausroll/material/small_strain_model.h>

#include "material_test_utilities.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace ausroll::material;
using dealii::SymmetricTensor;
using dealii::Tensor;

namespace
{
  MaterialParameters steel(const double H = 0., const double Hk = 0.)
  {
    MaterialParameters p;
    p.youngs_modulus = 210000.;
    p.poissons_ratio = 0.3;
    p.yield_stress = 240.;
    p.hardening_modulus = H;
    p.kinematic_hardening_modulus = Hk;
    return p;
  }

  /** F = I + grad u for a symmetric small strain. */
  Tensor<2, 3> deformation_from_strain(const SymmetricTensor<2, 3> &eps)
  {
    Tensor<2, 3> F = eps;
    for (unsigned int i = 0; i < 3; ++i)
      F[i][i] += 1.;
    return F;
  }

  /**
   * Uniaxial stress driver: given the axial strain, find the lateral strain e (eps_yy = eps_zz = e)
   * with sigma_yy = sigma_zz = 0, using the model's tangent. Returns the axial stress.
   */
  double uniaxial_stress(const ConstitutiveModel &model,
                         const double             axial_strain,
                         MaterialPoint           &point,
                         double                  &lateral_strain)
  {
    Tensor<2, 3> P;
    Tensor<4, 3> A;
    for (unsigned int it = 0; it < 50; ++it)
    {
      SymmetricTensor<2, 3> eps;
      eps[0][0] = axial_strain;
      eps[1][1] = eps[2][2] = lateral_strain;
      model.evaluate(deformation_from_strain(eps), point.committed, point.trial, P, &A);
      if (std::abs(P[1][1]) < 1e-10)
        break;
      lateral_strain -= P[1][1] / (A[1][1][1][1] + A[1][1][2][2]);
    }
    return P[0][0];
  }

  using ausroll::testing::tangent_error;
} // namespace

TEST(VonMises, ReturnsRadiallyOntoTheYieldSurface)
{
  const VonMisesPlasticity vm(steel(1000.));
  SymmetricTensor<2, 3>    trial;
  trial[0][0] = 500.;
  trial[1][1] = 100.;
  trial[0][1] = 80.;
  const ReturnMappingResult r = vm.return_map(trial, SymmetricTensor<2, 3>(), 0., 0.);
  ASSERT_TRUE(r.plastic);
  // on the (hardened) yield surface, with the same pressure and deviatoric direction as the trial
  EXPECT_NEAR(
      vm.yield_function(r.stress, r.back_stress, r.eq_plastic_strain_increment, 0.), 0., 1e-9);
  EXPECT_NEAR(dealii::trace(r.stress), dealii::trace(trial), 1e-9);
  const SymmetricTensor<2, 3> s = dealii::deviator(r.stress), st = dealii::deviator(trial);
  EXPECT_NEAR((s * st) / std::sqrt((s * s) * (st * st)), 1., 1e-12);
  // closed form: dgamma = (q_trial - sigma_y) / (3 mu + H)
  const double mu = vm.elasticity(0.).shear_modulus;
  const double q = std::sqrt(1.5 * (st * st));
  EXPECT_NEAR(r.eq_plastic_strain_increment, (q - 240.) / (3. * mu + 1000.), 1e-14);
}

TEST(VonMises, UniaxialTensionFollowsBilinearCurve)
{
  // Linear hardening: slope E before yield, tangent modulus E_t = E H / (E + H) after.
  const double     E = 210000., H = 2000., sy = 240.;
  SmallStrainModel model(std::make_unique<VonMisesPlasticity>(steel(H)));
  MaterialPoint    point;
  double           lateral = 0.;
  for (double eps = 0.0002; eps <= 0.02; eps += 0.0002)
  {
    const double sigma = uniaxial_stress(model, eps, point, lateral);
    point.commit();
    const double eps_y = sy / E;
    const double expected = eps <= eps_y ? E * eps : sy + E * H / (E + H) * (eps - eps_y);
    EXPECT_NEAR(sigma, expected, 1e-8 * expected) << "at strain " << eps;
  }
  // plastic strain in the axial direction: eps_p = (sigma - sy) / H
  const double sigma = point.committed.stress[0][0];
  EXPECT_NEAR(point.committed.plastic_strain[0][0], (sigma - sy) / H, 1e-10);
  EXPECT_NEAR(point.committed.equivalent_plastic_strain, (sigma - sy) / H, 1e-10);
  // plastic incompressibility
  EXPECT_NEAR(dealii::trace(point.committed.plastic_strain), 0., 1e-14);
}

TEST(VonMises, SimpleShearMatchesClosedForm)
{
  // tau(gamma) = G gamma before yield, (gamma + sqrt3 sy / H) / (1/G + 3/H) after.
  const double     H = 5000., sy = 240.;
  SmallStrainModel model(std::make_unique<VonMisesPlasticity>(steel(H)));
  const double     G = model.plasticity().elasticity(0.).shear_modulus;
  MaterialPoint    point;
  Tensor<2, 3>     P;
  for (double gamma = 0.0005; gamma <= 0.03; gamma += 0.0005)
  {
    SymmetricTensor<2, 3> eps;
    eps[0][1] = 0.5 * gamma;
    model.evaluate(deformation_from_strain(eps), point.committed, point.trial, P, nullptr);
    point.commit();
    const double tau_y = sy / std::sqrt(3.);
    const double expected
        = G * gamma <= tau_y ? G * gamma : (gamma + std::sqrt(3.) * sy / H) / (1. / G + 3. / H);
    EXPECT_NEAR(P[0][1], expected, 1e-9 * expected) << "at shear strain " << gamma;
    EXPECT_NEAR(P[0][0], 0., 1e-9);
  }
}

TEST(VonMises, PowerLawUniaxialIsExactForProportionalLoading)
{
  // sigma = s0 (1 + eps_p/e0)^n and eps = sigma/E + eps_p in uniaxial stress, in one big step
  // and in many small ones (radial return is exact for proportional loading).
  MaterialParameters p = steel();
  p.hardening_law = HardeningLawType::power_law;
  p.reference_plastic_strain = 0.002;
  p.hardening_exponent = 0.25;
  SmallStrainModel model(std::make_unique<VonMisesPlasticity>(p));
  const double     eps = 0.05, E = p.youngs_modulus.value(0.);

  // reference: solve sigma = s0 (1 + (eps - sigma/E)/e0)^n by bisection
  double lo = 240., hi = 2000.;
  for (int i = 0; i < 200; ++i)
  {
    const double mid = 0.5 * (lo + hi);
    const double g = mid - 240. * std::pow(1. + (eps - mid / E) / 0.002, 0.25);
    (g > 0 ? hi : lo) = mid;
  }
  const double reference = 0.5 * (lo + hi);

  MaterialPoint one_step;
  double        lateral = 0.;
  EXPECT_NEAR(uniaxial_stress(model, eps, one_step, lateral), reference, 1e-8 * reference);

  MaterialPoint many_steps;
  lateral = 0.;
  double sigma = 0.;
  for (int k = 1; k <= 100; ++k)
  {
    sigma = uniaxial_stress(model, eps * k / 100., many_steps, lateral);
    many_steps.commit();
  }
  EXPECT_NEAR(sigma, reference, 1e-8 * reference);
}

TEST(VonMises, KinematicHardeningShowsBauschingerEffect)
{
  // Prager hardening (H_k) in uniaxial stress: after tension to sigma_max the reverse yield
  // starts at sigma_max - 2 sy (yield surface translated, not expanded).
  const double     Hk = 20000.;
  SmallStrainModel model(std::make_unique<VonMisesPlasticity>(steel(0., Hk)));
  MaterialPoint    point;
  double           lateral = 0.;
  double           sigma_max = 0.;
  for (double eps = 0.0005; eps <= 0.01 + 1e-12; eps += 0.0005)
  {
    sigma_max = uniaxial_stress(model, eps, point, lateral);
    point.commit();
  }
  EXPECT_GT(sigma_max, 300.);
  // unload in small steps and find where the stress-strain slope departs from E
  const double E = 210000.;
  double       previous = sigma_max, eps = 0.01;
  double       reverse_yield = 0.;
  for (int k = 0; k < 4000; ++k)
  {
    eps -= 0.000005;
    const double s = uniaxial_stress(model, eps, point, lateral);
    point.commit();
    if (std::abs((previous - s) / 0.000005 - E) > 1e-3 * E)
    {
      reverse_yield = previous;
      break;
    }
    previous = s;
  }
  EXPECT_NEAR(reverse_yield, sigma_max - 2. * 240., 2.);
}

TEST(SmallStrainModel, TangentMatchesFiniteDifferences)
{
  std::mt19937                           rng(42);
  std::uniform_real_distribution<double> u(-1., 1.);
  for (const auto &mat : {steel(0.), steel(3000.), steel(1000., 5000.)})
  {
    SmallStrainModel model(std::make_unique<VonMisesPlasticity>(mat));
    for (int sample = 0; sample < 10; ++sample)
    {
      // plastic history, then a plastic trial step in another direction
      MaterialPoint         point;
      SymmetricTensor<2, 3> eps;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = i; j < 3; ++j)
          eps[i][j] = 0.004 * u(rng);
      Tensor<2, 3> P;
      model.evaluate(deformation_from_strain(eps), point.committed, point.trial, P, nullptr);
      point.commit();
      SymmetricTensor<2, 3> deps;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = i; j < 3; ++j)
          deps[i][j] = 0.003 * u(rng);
      EXPECT_LT(tangent_error(model, point.committed, deformation_from_strain(eps + deps)), 1e-6);
      // elastic unloading from a plastic state
      EXPECT_LT(tangent_error(model, point.committed, deformation_from_strain(eps - 0.0001 * eps)),
                1e-6);
    }
  }
}

TEST(PlaneStress, DriverGivesZeroNormalStressAndConsistentTangent)
{
  auto          model = create_constitutive_model(KinematicsType::small_strain, steel(2000.), true);
  MaterialPoint point;
  Tensor<2, 3>  F;
  F[0][0] = 1.004;
  F[1][1] = 0.999;
  F[0][1] = F[1][0] = 0.0015;
  F[2][2] = 1.;
  Tensor<2, 3> P;
  Tensor<4, 3> A;
  model->evaluate(F, point.committed, point.trial, P, &A);
  EXPECT_NEAR(P[2][2], 0., 1e-6);
  EXPECT_GT(point.trial.equivalent_plastic_strain, 0.);
  // thickness strain is negative under in-plane tension (plastic incompressibility + elastic nu)
  EXPECT_LT(point.trial.deformation_gradient[2][2], 1.);

  // in-plane tangent vs finite differences (F_zz re-solved in each perturbed evaluation)
  const double h = 1e-7;
  double       max_err = 0.;
  for (unsigned int k = 0; k < 2; ++k)
    for (unsigned int l = 0; l < 2; ++l)
    {
      Tensor<2, 3> Fp = F, Fm = F, Pp, Pm;
      Fp[k][l] += h;
      Fm[k][l] -= h;
      MaterialState s;
      model->evaluate(Fp, point.committed, s, Pp, nullptr);
      model->evaluate(Fm, point.committed, s, Pm, nullptr);
      for (unsigned int i = 0; i < 2; ++i)
        for (unsigned int j = 0; j < 2; ++j)
          max_err = std::max(max_err, std::abs((Pp[i][j] - Pm[i][j]) / (2 * h) - A[i][j][k][l]));
    }
  EXPECT_LT(max_err / 210000., 1e-6);
}

TEST(PlaneStress, UniaxialYieldIsTheUniaxialYieldStress)
{
  // In plane stress, pulling in x with sigma_yy = 0 is uniaxial: yield at sigma_y.
  auto          model = create_constitutive_model(KinematicsType::small_strain, steel(0.), true);
  MaterialPoint point;
  double        e_yy = 0.;
  Tensor<2, 3>  P;
  Tensor<4, 3>  A;
  for (int it = 0; it < 30; ++it)
  {
    Tensor<2, 3> F;
    F[0][0] = 1.01;
    F[1][1] = 1. + e_yy;
    F[2][2] = 1.;
    model->evaluate(F, point.committed, point.trial, P, &A);
    e_yy -= P[1][1] / A[1][1][1][1];
  }
  EXPECT_NEAR(P[1][1], 0., 1e-8);
  EXPECT_NEAR(P[0][0], 240., 1e-8);
}

TEST(MaterialState, PackUnpackRoundTrip)
{
  MaterialState s;
  s.stress[0][1] = 3.5;
  s.plastic_strain[2][2] = -0.01;
  s.back_stress[1][1] = 12.;
  s.elastic_left_cauchy_green[0][0] = 1.2;
  s.deformation_gradient[1][0] = 0.3;
  s.equivalent_plastic_strain = 0.25;
  std::vector<double> data;
  s.pack(data);
  ASSERT_EQ(data.size(), MaterialState::n_packed_values);
  MaterialState t;
  t.unpack(data.data());
  EXPECT_EQ(t.stress[0][1], 3.5);
  EXPECT_EQ(t.plastic_strain[2][2], -0.01);
  EXPECT_EQ(t.back_stress[1][1], 12.);
  EXPECT_EQ(t.elastic_left_cauchy_green[0][0], 1.2);
  EXPECT_EQ(t.deformation_gradient[1][0], 0.3);
  EXPECT_EQ(t.equivalent_plastic_strain, 0.25);
}

TEST(MaterialParameters, RejectsBadValuesWithTheEntryName)
{
  dealii::ParameterHandler prm;
  MaterialParameters::declare_parameters(prm);
  prm.parse_input_from_string("subsection Material\n set Hardening law = power law\n"
                              " set Reference plastic strain = 0\nend\n");
  MaterialParameters p;
  try
  {
    p.parse_parameters(prm);
    FAIL() << "expected an InputError";
  }
  catch (const ausroll::InputError &e)
  {
    EXPECT_NE(std::string(e.what()).find("Material/Reference plastic strain"), std::string::npos);
  }
}
