/**
 * @file test_assembly_cache.cc
 * mechanics::AssemblyCache: an assembly at the same state (displacement bit for bit, time, state
 * counter) reuses the cell part of the last one and gives exactly the targets of a full
 * assembly (tolerance 0: the same numbers go through the same condensation), also with other
 * row transforms (a contact status change); any change of the displacement, the time or the
 * state counter, or a tangent asked of a residual-only cache, computes the cells anew. Plastic
 * finite-strain material with F-bar and follower pressure (the test problem of
 * test_assembler_threads.cc).
 */
#include "support/assembler_test_problem.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace dealii;
using namespace ausroll;

namespace
{
  struct Result
  {
    std::vector<double> residual, external, free, rhs, matrix;
  };
} // namespace

TEST(AssemblyCache, ReuseAtTheSameStateIsExact)
{
  test_support::AssemblerTestProblem<2> problem(
      test_support::plastic_block_under_pressure("300 * (1 + 0.1 * x)"),
      test_support::rectangle({8, 4}, Point<2>(0., 0.), Point<2>(4., 2.)));
  for (unsigned int i = 0; i < problem.n_dofs(); ++i)
    problem.u[i] = 0.01 * std::sin(0.37 * i);

  // two sets of row transforms: the status change between two assemblies at one state
  const mechanics::RowTransforms<2> none;
  const mechanics::RowTransforms<2> one = test_support::slipping_node_transform();

  mechanics::AssemblyCache cache;
  auto                     run = [&](const TrilinosWrappers::MPI::Vector &u,
                 const double                         time,
                 const mechanics::RowTransforms<2>   &transforms,
                 const bool                           with_matrix,
                 mechanics::AssemblyCache            *with_cache)
  {
    const mechanics::AssemblyTargets targets = problem.targets(with_matrix, true);
    for (auto *v : {targets.residual, targets.external_force, targets.free_residual, targets.rhs})
      if (v != nullptr)
        *v = 0.;
    if (targets.matrix != nullptr)
      *targets.matrix = 0.;
    const auto status = problem.assembler.assemble(problem.dof_handler,
                                                   u,
                                                   time,
                                                   problem.points,
                                                   problem.none,
                                                   problem.none,
                                                   &transforms,
                                                   targets,
                                                   with_cache);
    EXPECT_TRUE(status.ok) << status.message;
    Result r{test_support::values(problem.residual),
             test_support::values(problem.external),
             test_support::values(problem.free_residual),
             {},
             {}};
    if (with_matrix)
    {
      r.rhs = test_support::values(problem.rhs);
      for (const auto &entry : problem.matrix)
        r.matrix.push_back(entry.value());
    }
    return r;
  };
  auto expect_equal = [](const Result &a, const Result &b)
  {
    EXPECT_EQ(a.residual, b.residual);
    EXPECT_EQ(a.external, b.external);
    EXPECT_EQ(a.free, b.free);
    EXPECT_EQ(a.rhs, b.rhs);
    EXPECT_EQ(a.matrix, b.matrix);
  };

  const Result full_none = run(problem.u, 1., none, true, nullptr);
  const Result full_one = run(problem.u, 1., one, true, nullptr);
  EXPECT_NE(full_none.free, full_one.free); // the transforms matter

  expect_equal(run(problem.u, 1., none, true, &cache), full_none); // computed, stored
  EXPECT_EQ(cache.misses, 1u);
  expect_equal(run(problem.u, 1., one, true, &cache), full_one); // reused: other transforms
  EXPECT_EQ(cache.hits, 1u);
  // a residual-only request is served by a cache with the tangent
  const Result residual_only = run(problem.u, 1., one, false, &cache);
  EXPECT_EQ(cache.hits, 2u);
  EXPECT_EQ(residual_only.free, full_one.free);

  // the state counter (commit, restore, transfer) invalidates
  ++cache.state;
  expect_equal(run(problem.u, 1., one, true, &cache), full_one);
  EXPECT_EQ(cache.misses, 2u);

  // another time invalidates (surface loads are time dependent)
  run(problem.u, 2., one, true, &cache);
  EXPECT_EQ(cache.misses, 3u);

  // one changed displacement entry invalidates; the result is that of a full assembly there
  TrilinosWrappers::MPI::Vector v(problem.u);
  v[3] += 1e-12;
  const Result full_v = run(v, 1., one, true, nullptr);
  expect_equal(run(v, 1., one, true, &cache), full_v);
  EXPECT_EQ(cache.misses, 4u);
  EXPECT_NE(full_v.residual, full_one.residual);

  // a residual-only cache cannot give the tangent
  ++cache.state;
  run(v, 1., one, false, &cache);
  EXPECT_EQ(cache.misses, 5u);
  expect_equal(run(v, 1., one, true, &cache), full_v);
  EXPECT_EQ(cache.misses, 6u);
  EXPECT_EQ(cache.hits, 2u);

  // a cache larger than its budget is not kept
  mechanics::AssemblyCache small;
  small.max_bytes = 16;
  run(v, 1., one, true, &small);
  run(v, 1., one, true, &small);
  EXPECT_EQ(small.hits, 0u);
  EXPECT_FALSE(small.valid);
}
