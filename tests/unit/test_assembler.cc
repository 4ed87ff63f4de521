// Unit tests of the assembler: the tangent matrix is the exact derivative of the residual for
// every kinematics, with and without F-bar, plane strain and axisymmetric, Q1 and Q2, with the
// follower pressure (load stiffness) on a deformed, distorted mesh (central finite differences of
// the residual, column by column).
#include "support/assembler_test_problem.h"

#include <deal.II/lac/vector.h>

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
    mechanics::PlanarModel       planar;
    mechanics::VolumetricLocking locking;
    unsigned int                 degree;
    bool                         plastic;
  };

  std::string label(const Case &c)
  {
    return material::to_string(c.kinematics) + ", "
           + (c.planar == mechanics::PlanarModel::axisymmetric ? "axisymmetric" : "plane strain")
           + ", Q" + std::to_string(c.degree)
           + (c.locking == mechanics::VolumetricLocking::f_bar ? ", F-bar" : "")
           + (c.plastic ? ", plastic" : ", elastic");
  }

  /**
   * Max |K_fd - K| / max |K| on a 2 x 2 cell block [1, 2.2] x [0, 1.1] (distorted interior
   * vertex) with a random displacement of amplitude 0.08, a pressure of 30 on the top (boundary 3)
   * and a dead traction on the right (boundary 1). Central differences with h = 1e-7.
   */
  double tangent_error(const Case &c)
  {
    test_support::AssemblerTestOptions options = test_support::tangent_test_options(
        c.kinematics, c.degree, c.plastic, c.planar, c.locking);
    options.conditions = test_support::tangent_test_loads();
    test_support::AssemblerTestProblem<2> problem(options, test_support::distorted_block());
    const unsigned int                    n = problem.n_dofs();
    TrilinosWrappers::MPI::Vector        &u = problem.u;
    const TrilinosWrappers::MPI::Vector  &residual = problem.residual;
    const TrilinosWrappers::SparseMatrix &matrix = problem.matrix;

    std::mt19937                           rng(11);
    std::uniform_real_distribution<double> uniform(-1., 1.);
    for (unsigned int i = 0; i < n; ++i)
      u[i] = 0.08 * uniform(rng);

    auto assemble = [&](const TrilinosWrappers::MPI::Vector &at, const bool with_matrix)
    {
      const auto status = problem.assemble(at, with_matrix);
      EXPECT_TRUE(status.ok) << status.message;
    };

    assemble(u, true);
    if (c.plastic)
    {
      EXPECT_GT(problem.n_plastic_points(), 0u) << label(c);
    }
    double scale = 0.;
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        scale = std::max(scale, std::abs(matrix.el(i, j)));

    const double   h = 1e-7;
    double         max_error = 0.;
    Vector<double> r_plus(n), r_minus(n);
    for (unsigned int j = 0; j < n; ++j)
    {
      TrilinosWrappers::MPI::Vector v = u;
      v[j] += h;
      assemble(v, false);
      for (unsigned int i = 0; i < n; ++i)
        r_plus[i] = residual[i];
      v[j] -= 2. * h;
      assemble(v, false);
      for (unsigned int i = 0; i < n; ++i)
        r_minus[i] = residual[i];
      for (unsigned int i = 0; i < n; ++i)
        max_error
            = std::max(max_error, std::abs((r_plus[i] - r_minus[i]) / (2. * h) - matrix.el(i, j)));
    }
    return max_error / scale;
  }
} // namespace

TEST(Assembler, TangentMatchesFiniteDifferencesOfResidual)
{
  using K = material::KinematicsType;
  using L = mechanics::VolumetricLocking;
  using M = mechanics::PlanarModel;
  std::vector<Case> cases;
  for (const K k : {K::small_strain, K::total_lagrangian, K::updated_lagrangian, K::finite_strain})
    for (const M m : {M::plane_strain, M::axisymmetric})
      for (const L l : {L::none, L::f_bar})
        cases.push_back({k, m, l, 1, true});
  // Q2 with F-bar (cell-average J0), elastic and plastic; the follower pressure alone (no F-bar,
  // elastic)
  for (const M m : {M::plane_strain, M::axisymmetric})
  {
    cases.push_back({K::finite_strain, m, L::f_bar, 2, true});
    cases.push_back({K::finite_strain, m, L::none, 2, false});
    cases.push_back({K::updated_lagrangian, m, L::f_bar, 2, false});
    cases.push_back({K::small_strain, m, L::f_bar, 2, true});
  }
  for (const Case &c : cases)
  {
    const double err = tangent_error(c);
    std::printf("[ assembler ] %-55s tangent FD error %.2e\n", label(c).c_str(), err);
    EXPECT_LT(err, 1e-6) << label(c);
  }
}

// The hoop entry the assembly terms are specialised on (PlanarKinematics::with_hoop_entry()) is
// the out-of-plane entry of the kinematics' own 3D shape gradient and deformation gradient
// (PlanarKinematics::shape_gradient(), deformation_gradient(): an independent implementation),
// for every planar model and both components; exact, the same operations (phi / R, 1 + u_r / R).
TEST(Assembler, HoopEntryIsTheOutOfPlaneEntryOfTheKinematics)
{
  using M = mechanics::PlanarModel;
  const Point<2> X(1.7, 0.4);
  for (const M m : {M::plane_strain, M::plane_stress, M::axisymmetric})
  {
    const mechanics::PlanarKinematics<2> kinematics(m, 2.5);
    kinematics.with_hoop_entry(
        [&](auto hoop)
        {
          using Hoop = decltype(hoop);
          EXPECT_EQ(Hoop::n_entries, m == M::axisymmetric ? 1u : 0u);
          for (unsigned int c = 0; c < 2; ++c)
          {
            Tensor<1, 2> phi;
            phi[c] = 0.37;
            Tensor<2, 2> grad_phi;
            grad_phi[c][0] = 0.11;
            grad_phi[c][1] = -0.23;
            const double expected = kinematics.shape_gradient(grad_phi, phi, X)[2][2];
            const double entry = Hoop::has_entry(c) ? Hoop::entry(phi[c], X) : 0.;
            EXPECT_EQ(entry, expected) << "component " << c;
            EXPECT_EQ(Hoop::product(3., entry), 3. * expected) << "component " << c;
          }
          const Tensor<1, 2> u({0.21, -0.05});
          EXPECT_EQ(Hoop::stretch(u, X),
                    kinematics.deformation_gradient(Tensor<2, 2>(), u, X)[2][2]);
        });
  }
  // 3D: no hoop entry
  const mechanics::PlanarKinematics<3> kinematics_3d(M::axisymmetric, 1.);
  kinematics_3d.with_hoop_entry([](auto hoop) { EXPECT_EQ(decltype(hoop)::n_entries, 0u); });
}
