/**
 * @file test_assembler_threads.cc
 * The WorkStream cell loop of mechanics::Assembler gives the same residual, external force,
 * free residual, tangent and right-hand side on 2 and on 4 threads as on 1 (which runs the cells
 * in order, as the former serial loop): exactly equal, tolerance 0, because the copier adds the
 * cells to the global objects in cell order whatever thread computed them (the sums are the
 * serial sums term by term, so not even round-off may differ). Plastic finite-strain material
 * with F-bar, follower pressure, and a friction row transform with offset on a surface node.
 */
#include "support/assembler_test_problem.h"

#include <deal.II/base/multithread_info.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

using namespace dealii;
using namespace ausroll;

TEST(AssemblerThreads, TwoAndFourThreadsEqualOneThreadExactly)
{
  test_support::AssemblerTestProblem<2> problem(
      test_support::plastic_block_under_pressure("300 * (1 + 0.1 * x)"),
      test_support::rectangle({12, 6}, Point<2>(0., 0.), Point<2>(4., 2.)));
  for (unsigned int i = 0; i < problem.n_dofs(); ++i)
    problem.u[i] = 0.01 * std::sin(0.37 * i);

  // a slipping node's row transform (matrix and constant offset) on DoFs 0, 1
  const mechanics::RowTransforms<2> transforms = test_support::slipping_node_transform();

  struct Result
  {
    std::vector<double> residual, external, free, rhs, matrix;
  };
  auto run = [&](const unsigned int n_threads)
  {
    MultithreadInfo::set_thread_limit(n_threads);
    EXPECT_EQ(MultithreadInfo::n_threads(), n_threads);
    const auto status
        = problem.assemble(problem.u, problem.targets(true, true), nullptr, &transforms);
    EXPECT_TRUE(status.ok) << status.message;
    Result r{test_support::values(problem.residual),
             test_support::values(problem.external),
             test_support::values(problem.free_residual),
             test_support::values(problem.rhs),
             {}};
    for (const auto &entry : problem.matrix)
      r.matrix.push_back(entry.value());
    return r;
  };

  // DEAL_II_NUM_THREADS (CI sets 1) caps set_thread_limit(): lift it for this test only
  const char       *env = std::getenv("DEAL_II_NUM_THREADS");
  const std::string saved = env != nullptr ? env : "";
  unsetenv("DEAL_II_NUM_THREADS");
  const Result one = run(1);
  const Result two = run(2);
  const Result four = run(4);
  if (env != nullptr)
    setenv("DEAL_II_NUM_THREADS", saved.c_str(), 1);
  MultithreadInfo::set_thread_limit(1);
  for (const Result *other : {&two, &four})
  {
    EXPECT_EQ(one.residual, other->residual);
    EXPECT_EQ(one.external, other->external);
    EXPECT_EQ(one.free, other->free);
    EXPECT_EQ(one.rhs, other->rhs);
    EXPECT_EQ(one.matrix, other->matrix);
  }
  // the offset was added once: free residual = transformed residual + offset at DoF 0
  EXPECT_NEAR(one.free[0],
              one.residual[0] + 0.3 * one.residual[1] + 2.5,
              1e-9 * (1. + std::abs(one.free[0])));
  EXPECT_EQ(one.free[1], one.residual[1]);
}
