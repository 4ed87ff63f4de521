// Unit tests of the assembler: the tangent matrix is the exact derivative of the residual for
// every kinematics, with and without F-bar, plane strain and axisymmetric, Q1 and Q2, with the
// follower pressure (load stiffness) on a deformed, distorted mesh (central finite differences of
// the residual, column by column).
#include <ausroll/material/constitutive_model.h>
#include <ausroll/mechanics/assembler.h>
#include <ausroll/mechanics/boundary_conditions.h>
#include <ausroll/mechanics/planar_kinematics.h>

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <gtest/gtest.h>

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
    Triangulation<2> tria;
    GridGenerator::subdivided_hyper_rectangle(
        tria, {2, 2}, Point<2>(1., 0.), Point<2>(2.2, 1.1), /*colorize=*/true);
    for (auto &cell : tria.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        if (std::abs(cell->vertex(v)[0] - 1.6) < 1e-12
            && std::abs(cell->vertex(v)[1] - 0.55) < 1e-12)
          cell->vertex(v) += Point<2>(0.07, -0.05);

    FESystem<2>   fe(FE_Q<2>(c.degree), 2);
    MappingQ<2>   mapping(c.degree);
    DoFHandler<2> dof_handler(tria);
    dof_handler.distribute_dofs(fe);
    const unsigned int n = dof_handler.n_dofs();

    material::MaterialParameters mat;
    mat.youngs_modulus = 1000.;
    mat.poissons_ratio = 0.3;
    mat.yield_stress = c.plastic ? 2. : 1e9;
    mat.hardening_modulus = 50.;
    mat.kinematic_hardening_modulus = c.plastic ? 30. : 0.;
    const auto model = material::create_constitutive_model(c.kinematics, mat, false);

    mechanics::BoundaryConditionParameters bc_parameters;
    mechanics::BoundaryCondition           pressure, traction;
    pressure.id = 3;
    pressure.type = mechanics::BoundaryConditionType::pressure;
    pressure.value = "30 + 5 * x";
    traction.id = 1;
    traction.type = mechanics::BoundaryConditionType::traction;
    traction.value = "4; -3 * y";
    bc_parameters.conditions = {pressure, traction};
    const mechanics::BoundaryConditions<2> bcs(bc_parameters);
    const mechanics::PlanarKinematics<2>   kinematics(c.planar, 1.);
    const mechanics::Assembler<2>          assembler(
        mapping, fe, c.degree + 1, kinematics, *model, bcs, c.locking);

    mechanics::MaterialPointStorage<2> points;
    points.initialize(tria.begin_active(), tria.end(), assembler.quadrature().size());

    const IndexSet            all = complete_index_set(n);
    AffineConstraints<double> none;
    none.close();
    DynamicSparsityPattern dsp(n, n);
    DoFTools::make_sparsity_pattern(dof_handler, dsp);
    TrilinosWrappers::SparseMatrix matrix;
    matrix.reinit(all, all, dsp, MPI_COMM_WORLD);
    TrilinosWrappers::MPI::Vector u(all, MPI_COMM_WORLD), residual(all, MPI_COMM_WORLD),
        external(all, MPI_COMM_WORLD), rhs(all, MPI_COMM_WORLD);

    std::mt19937                           rng(11);
    std::uniform_real_distribution<double> uniform(-1., 1.);
    for (unsigned int i = 0; i < n; ++i)
      u[i] = 0.08 * uniform(rng);

    auto assemble = [&](const TrilinosWrappers::MPI::Vector &at, const bool with_matrix)
    {
      residual = 0.;
      external = 0.;
      mechanics::AssemblyTargets targets;
      targets.residual = &residual;
      targets.external_force = &external;
      if (with_matrix)
      {
        matrix = 0.;
        rhs = 0.;
        targets.matrix = &matrix;
        targets.rhs = &rhs;
      }
      const auto status
          = assembler.assemble(dof_handler, at, 1., points, none, none, nullptr, targets);
      EXPECT_TRUE(status.ok) << status.message;
    };

    assemble(u, true);
    if (c.plastic)
    {
      unsigned int n_plastic = 0;
      for (const auto &cell : tria.active_cell_iterators())
        for (const auto &p : points.get_data(cell))
          n_plastic += p->trial.equivalent_plastic_strain > 0.;
      EXPECT_GT(n_plastic, 0u) << label(c);
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
