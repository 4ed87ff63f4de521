/**
 * @file test_yield_criterion_seam.cc
 * The yield-criterion seam of material::PlasticityModel: the finite-strain kinematics call the
 * criterion's own back_stress_sensitivity() (a virtual override), not a J2 formula of their own.
 * A model derived from VonMisesPlasticity counts the calls and can return a wrong sensitivity:
 * the count must grow in a plastic step with a rotated back stress, the right sensitivity keeps
 * the tangent equal to central differences (1e-6, the tolerance of the finite-strain tangent
 * tests), and the wrong one (zero) spoils it (error above 1e-4), so the override's value is the
 * one used.
 */
#include <ausroll/material/constitutive_model.h>
#include <ausroll/material/finite_strain_log_model.h>
#include <ausroll/material/material_point.h>
#include <ausroll/material/plasticity_model.h>
#include <ausroll/material/updated_lagrangian_jaumann_model.h>

#include <deal.II/base/symmetric_tensor.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>

#include "material_test_utilities.h"

using namespace ausroll::material;
using dealii::SymmetricTensor;
using dealii::Tensor;

namespace
{
  /** von Mises with a counted (and optionally wrong) back-stress sensitivity. */
  class CountingVonMises : public VonMisesPlasticity
  {
  public:
    CountingVonMises(const MaterialParameters &p, unsigned int &calls, const bool wrong)
        : VonMisesPlasticity(p)
        , calls(calls)
        , wrong(wrong)
    {
    }
    SymmetricTensor<4, 3> back_stress_sensitivity(const ReturnMappingResult &result,
                                                  const double temperature) const override
    {
      ++calls;
      return wrong ? SymmetricTensor<4, 3>()
                   : VonMisesPlasticity::back_stress_sensitivity(result, temperature);
    }

  private:
    unsigned int &calls;
    const bool    wrong;
  };

  MaterialParameters hardening_steel()
  {
    MaterialParameters p;
    p.youngs_modulus = 210000.;
    p.poissons_ratio = 0.3;
    p.yield_stress = 240.;
    p.hardening_modulus = 1000.;
    p.kinematic_hardening_modulus = 5000.;
    return p;
  }

  /** R(theta about z) diag(1 + 0.2 s, 1 - 0.1 s, 1): stretch and rotation growing with s. */
  Tensor<2, 3> path(const double s)
  {
    const double theta = 30. * M_PI / 180. * s;
    Tensor<2, 3> R, U;
    R[0][0] = R[1][1] = std::cos(theta);
    R[0][1] = -std::sin(theta);
    R[1][0] = std::sin(theta);
    R[2][2] = 1.;
    U[0][0] = 1. + 0.2 * s;
    U[1][1] = 1. - 0.1 * s;
    U[2][2] = 1.;
    U[0][1] = U[1][0] = 0.05 * s;
    return R * U;
  }

  void check_kinematics(
      const std::function<std::unique_ptr<ConstitutiveModel>(std::unique_ptr<PlasticityModel>)>
                 &make,
      const char *label)
  {
    for (const bool wrong : {false, true})
    {
      unsigned int calls = 0;
      const auto model = make(std::make_unique<CountingVonMises>(hardening_steel(), calls, wrong));
      MaterialPoint point;
      Tensor<2, 3>  P;
      for (unsigned int k = 1; k <= 20; ++k)
      {
        model->evaluate(path(0.05 * k), point.committed, point.trial, P, nullptr);
        point.commit();
      }
      ASSERT_GT(point.committed.back_stress.norm(), 10.) << label;
      calls = 0;
      const double error = ausroll::testing::tangent_error(*model, point.committed, path(1.1));
      EXPECT_GT(calls, 0u) << label << ": the override was not called";
      if (wrong)
        EXPECT_GT(error, 1e-4) << label << ": a wrong sensitivity left the tangent unchanged";
      else
        EXPECT_LT(error, 1e-6) << label;
    }
  }
} // namespace

TEST(YieldCriterionSeam, FiniteStrainModelUsesTheOverride)
{
  check_kinematics([](std::unique_ptr<PlasticityModel> p)
                   { return std::make_unique<FiniteStrainLogModel>(std::move(p)); },
                   "finite strain");
}

TEST(YieldCriterionSeam, UpdatedLagrangianModelUsesTheOverride)
{
  check_kinematics([](std::unique_ptr<PlasticityModel> p)
                   { return std::make_unique<UpdatedLagrangianJaumannModel>(std::move(p)); },
                   "updated Lagrangian");
}

TEST(YieldCriterionSeam, ElasticModelHasNoBackStressSensitivity)
{
  MaterialParameters p = hardening_steel();
  p.yield_criterion = YieldCriterion::none;
  const auto                model = create_plasticity_model(p);
  const ReturnMappingResult r
      = model->return_map(SymmetricTensor<2, 3>(), SymmetricTensor<2, 3>(), 0., 0.);
  EXPECT_EQ(model->back_stress_sensitivity(r, 0.).norm(), 0.);
}
