/**
 * @file test_assembler_threads.cc
 * The WorkStream cell loop of mechanics::Assembler gives the same residual, external force,
 * free residual, tangent and right-hand side on 2 threads as on 1 (which runs the cells in order,
 * as the former serial loop): exactly equal, tolerance 0, because the copier adds the cells to
 * the global objects in cell order whatever thread computed them. Plastic finite-strain material
 * with F-bar, follower pressure, and a friction row transform with offset on a surface node.
 */
#include <ausroll/material/constitutive_model.h>
#include <ausroll/mechanics/assembler.h>
#include <ausroll/mechanics/boundary_conditions.h>
#include <ausroll/mechanics/planar_kinematics.h>

#include <deal.II/base/multithread_info.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

using namespace dealii;
using namespace ausroll;

TEST(AssemblerThreads, TwoThreadsEqualOneThreadExactly)
{
  Triangulation<2> tria;
  GridGenerator::subdivided_hyper_rectangle(
      tria, {12, 6}, Point<2>(0., 0.), Point<2>(4., 2.), /*colorize=*/true);
  FESystem<2>   fe(FE_Q<2>(2), 2);
  MappingQ<2>   mapping(2);
  DoFHandler<2> dof_handler(tria);
  dof_handler.distribute_dofs(fe);
  const unsigned int n = dof_handler.n_dofs();

  material::MaterialParameters mat;
  mat.yield_stress = 240.;
  mat.hardening_modulus = 1000.;
  const auto model
      = material::create_constitutive_model(material::KinematicsType::finite_strain, mat, false);
  mechanics::BoundaryConditionParameters bc_parameters;
  mechanics::BoundaryCondition           pressure;
  pressure.id = 3;
  pressure.type = mechanics::BoundaryConditionType::pressure;
  pressure.value = "300 * (1 + 0.1 * x)";
  bc_parameters.conditions = {pressure};
  const mechanics::BoundaryConditions<2> bcs(bc_parameters);
  const mechanics::PlanarKinematics<2>   kinematics(mechanics::PlanarModel::plane_strain, 1.);
  const mechanics::Assembler<2>          assembler(
      mapping, fe, 3, kinematics, *model, bcs, mechanics::VolumetricLocking::f_bar);
  mechanics::MaterialPointStorage<2> points;
  points.initialize(tria.begin_active(), tria.end(), assembler.quadrature().size());

  const IndexSet            all = complete_index_set(n);
  AffineConstraints<double> none;
  none.close();
  DynamicSparsityPattern dsp(n, n);
  DoFTools::make_sparsity_pattern(dof_handler, dsp);
  TrilinosWrappers::MPI::Vector u(all, MPI_COMM_WORLD);
  for (unsigned int i = 0; i < n; ++i)
    u[i] = 0.01 * std::sin(0.37 * i);

  // a slipping node's row transform (matrix and constant offset) on DoFs 0, 1
  mechanics::RowTransforms<2>     transforms;
  mechanics::NodalRowTransform<2> t;
  t.dofs = {0, 1};
  t.matrix[0][0] = t.matrix[1][1] = 1.;
  t.matrix[0][1] = 0.3;
  t.offset[0] = 2.5;
  transforms.emplace(0, t);

  struct Result
  {
    std::vector<double> residual, external, free, rhs, matrix;
  };
  auto run = [&](const unsigned int n_threads)
  {
    MultithreadInfo::set_thread_limit(n_threads);
    EXPECT_EQ(MultithreadInfo::n_threads(), n_threads);
    TrilinosWrappers::SparseMatrix matrix;
    matrix.reinit(all, all, dsp, MPI_COMM_WORLD);
    TrilinosWrappers::MPI::Vector residual(all, MPI_COMM_WORLD), external(all, MPI_COMM_WORLD),
        free(all, MPI_COMM_WORLD), rhs(all, MPI_COMM_WORLD);
    mechanics::AssemblyTargets targets;
    targets.residual = &residual;
    targets.external_force = &external;
    targets.free_residual = &free;
    targets.matrix = &matrix;
    targets.rhs = &rhs;
    const auto status
        = assembler.assemble(dof_handler, u, 1., points, none, none, &transforms, targets);
    EXPECT_TRUE(status.ok) << status.message;
    Result r;
    for (unsigned int i = 0; i < n; ++i)
    {
      r.residual.push_back(residual[i]);
      r.external.push_back(external[i]);
      r.free.push_back(free[i]);
      r.rhs.push_back(rhs[i]);
    }
    for (const auto &entry : matrix)
      r.matrix.push_back(entry.value());
    return r;
  };

  // DEAL_II_NUM_THREADS (CI sets 1) caps set_thread_limit(): lift it for this test only
  const char       *env = std::getenv("DEAL_II_NUM_THREADS");
  const std::string saved = env != nullptr ? env : "";
  unsetenv("DEAL_II_NUM_THREADS");
  const Result one = run(1);
  const Result two = run(2);
  if (env != nullptr)
    setenv("DEAL_II_NUM_THREADS", saved.c_str(), 1);
  MultithreadInfo::set_thread_limit(1);
  EXPECT_EQ(one.residual, two.residual);
  EXPECT_EQ(one.external, two.external);
  EXPECT_EQ(one.free, two.free);
  EXPECT_EQ(one.rhs, two.rhs);
  EXPECT_EQ(one.matrix, two.matrix);
  // the offset was added once: free residual = transformed residual + offset at DoF 0
  EXPECT_NEAR(one.free[0],
              one.residual[0] + 0.3 * one.residual[1] + 2.5,
              1e-9 * (1. + std::abs(one.free[0])));
  EXPECT_EQ(one.free[1], one.residual[1]);
}
