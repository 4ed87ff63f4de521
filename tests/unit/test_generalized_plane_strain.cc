// Unit tests of generalized plane strain (mechanics::GeneralizedPlaneStrain): the border of the
// Newton system that the internal-force term assembles, k_ue = dr/dlambda, k_eu = dW/du and
// k_ee = dW/dlambda with W = int P_zz dV, against central finite differences of the residual
// and of W (the residual with the follower pressure, whose face is lambda dl long out of plane),
// for every kinematics, with and without F-bar (Q1: in-plane scaling, F_bar_zz =
// lambda; Q2: the whole F scaled, F_bar_zz = s lambda), elastic and plastic; and the kinematics'
// F_zz; and the in-plane tangent K at lambda != 1.
#include "support/assembler_test_problem.h"

#include <ausroll/mechanics/generalized_plane_strain.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

using namespace dealii;
using namespace ausroll;

namespace
{
  struct Case
  {
    material::KinematicsType     kinematics;
    mechanics::VolumetricLocking locking;
    unsigned int                 degree;
    bool                         plastic;
  };

  std::string label(const Case &c)
  {
    return material::to_string(c.kinematics) + ", Q" + std::to_string(c.degree)
           + (c.locking == mechanics::VolumetricLocking::f_bar ? ", F-bar" : "")
           + (c.plastic ? ", plastic" : ", elastic");
  }

  struct Errors
  {
    double column = 0., row = 0., corner = 0.; // relative to the largest entry of each
    double matrix = 0.; // the in-plane tangent K at lambda != 1, relative to max |K|
  };

  /**
   * The border at a random displacement (amplitude 0.08) and lambda = 1.03 on a 2 x 2 block
   * [1, 2.2] x [0, 1.1] with a distorted interior vertex, a pressure of 30 on the top (a follower
   * load on the deformed face, lambda dl long out of plane, but for small strain) and a dead
   * traction on the right; central differences with h = 1e-7.
   */
  Errors border_errors(const Case &c)
  {
    test_support::AssemblerTestOptions options
        = test_support::tangent_test_options(c.kinematics,
                                             c.degree,
                                             c.plastic,
                                             mechanics::PlanarModel::generalized_plane_strain,
                                             c.locking);
    options.conditions = test_support::tangent_test_loads();
    test_support::AssemblerTestProblem<2> problem(options, test_support::distorted_block());
    const unsigned int                    n = problem.n_dofs();
    TrilinosWrappers::MPI::Vector        &u = problem.u;
    const TrilinosWrappers::MPI::Vector  &residual = problem.residual;

    std::mt19937                           rng(5);
    std::uniform_real_distribution<double> uniform(-1., 1.);
    for (unsigned int i = 0; i < n; ++i)
      u[i] = 0.08 * uniform(rng);
    const double lambda = 1.03;

    mechanics::GeneralizedPlaneStrain gps;
    gps.active = true;
    gps.column = problem.vector();
    gps.row = problem.vector();
    // W = int P_zz dV at (v, l), the residual into problem.residual
    const auto assemble
        = [&](const TrilinosWrappers::MPI::Vector &v, const double l, const bool with_matrix)
    {
      problem.stretch = l;
      mechanics::AssemblyTargets targets = problem.targets(with_matrix);
      targets.out_of_plane = &gps;
      gps.column = 0.;
      gps.row = 0.;
      const auto status = problem.assemble(v, targets);
      EXPECT_TRUE(status.ok) << status.message;
      return gps.axial_work;
    };

    assemble(u, lambda, true);
    if (c.plastic)
    {
      EXPECT_GT(problem.n_plastic_points(), 0u) << label(c);
    }
    const std::vector<double> column = test_support::values(gps.column);
    const std::vector<double> row = test_support::values(gps.row);
    const double              stiffness = gps.stiffness;
    double                    matrix_scale = 0.;
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        matrix_scale = std::max(matrix_scale, std::abs(problem.matrix.el(i, j)));
    // the stretch is read through the kinematics: F_zz = lambda
    EXPECT_EQ(
        problem.kinematics.deformation_gradient(Tensor<2, 2>(), Tensor<1, 2>(), Point<2>())[2][2],
        lambda);

    const double h = 1e-7;
    Errors       e;
    double       column_scale = 0., row_scale = 0.;
    // k_ue and k_ee: differences in lambda
    const double        w_plus = assemble(u, lambda + h, false);
    std::vector<double> r_plus = test_support::values(residual);
    const double        w_minus = assemble(u, lambda - h, false);
    for (unsigned int i = 0; i < n; ++i)
    {
      column_scale = std::max(column_scale, std::abs(column[i]));
      e.column = std::max(e.column, std::abs((r_plus[i] - residual[i]) / (2. * h) - column[i]));
    }
    e.corner = std::abs((w_plus - w_minus) / (2. * h) - stiffness) / std::abs(stiffness);
    // k_eu and K: differences in u
    for (unsigned int j = 0; j < n; ++j)
    {
      TrilinosWrappers::MPI::Vector v = u;
      v[j] += h;
      const double plus = assemble(v, lambda, false);
      r_plus = test_support::values(residual);
      v[j] -= 2. * h;
      const double minus = assemble(v, lambda, false);
      for (unsigned int i = 0; i < n; ++i)
        e.matrix = std::max(
            e.matrix, std::abs((r_plus[i] - residual[i]) / (2. * h) - problem.matrix.el(i, j)));
      row_scale = std::max(row_scale, std::abs(row[j]));
      e.row = std::max(e.row, std::abs((plus - minus) / (2. * h) - row[j]));
    }
    e.column /= column_scale;
    e.row /= row_scale;
    e.matrix /= matrix_scale;
    return e;
  }
} // namespace

TEST(GeneralizedPlaneStrain, BorderMatchesFiniteDifferences)
{
  using K = material::KinematicsType;
  using L = mechanics::VolumetricLocking;
  std::vector<Case> cases;
  for (const K k : {K::small_strain, K::total_lagrangian, K::updated_lagrangian, K::finite_strain})
    for (const L l : {L::none, L::f_bar})
      cases.push_back({k, l, 1, true});
  cases.push_back({K::finite_strain, L::f_bar, 2, true}); // n = 3: F_bar_zz = s lambda
  cases.push_back({K::small_strain, L::f_bar, 2, true});
  cases.push_back({K::finite_strain, L::none, 2, false});
  for (const Case &c : cases)
  {
    const Errors e = border_errors(c);
    std::printf("[ gps ] %-40s FD error k_ue %.2e, k_eu %.2e, k_ee %.2e, K %.2e\n",
                label(c).c_str(),
                e.column,
                e.row,
                e.corner,
                e.matrix);
    EXPECT_LT(e.column, 1e-6) << label(c);
    EXPECT_LT(e.row, 1e-6) << label(c);
    EXPECT_LT(e.corner, 1e-6) << label(c);
    EXPECT_LT(e.matrix, 1e-6) << label(c);
  }
}
