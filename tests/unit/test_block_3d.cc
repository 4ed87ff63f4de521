/**
 * @file test_block_3d.cc
 * `Geometry/Type = block` with the symmetry planes of `Boundary conditions` in 3D (one component
 * per plane: u_x = 0 on x = 0, u_y = 0 on y = 0, u_z = 0 on z = 0) in uniaxial compression
 * against the homogeneous analytic solution, and the choice of `Solver/Linear solver/Type =
 * automatic` (direct below `Automatic iterative threshold` unknowns in 3D and always in 2D), and
 * the AMG solve on several ranks against one rank (ctest `unit/Block3dParallel.mpirun=2`).
 */
#include <ausroll/solver/linear_solver.h>
#include <ausroll/solver/solver_parameters.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include "support/block_3d_problem.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>

using namespace dealii;
using namespace ausroll;

namespace
{
  constexpr double E = 1000., nu = 0.3;

  /**
   * The block [0, 2] x [0, 1] x [0, 3] (Geometry/Block, cells 2 x 2 x 3, ids 0..5) with the
   * symmetry planes and the top z = 3 moved by -delta t, all read from a .prm text; elastic
   * small strain, Q@p degree, on one rank (test_support::Block3dProblem: assemble() gives the
   * Newton system at the current u).
   */
  std::unique_ptr<test_support::Block3dProblem> block_problem(const unsigned int degree,
                                                              const double       delta)
  {
    ParameterHandler prm;
    geometry::GeometryParameters::declare_parameters(prm);
    mechanics::BoundaryConditionParameters::declare_parameters(prm);
    std::string text = "subsection Geometry\nset Type = block\nsubsection Block\n"
                       "set Upper corner = 2, 1, 3\nset Cells = 2, 2, 3\nend\nend\n"
                       "subsection Boundary conditions\nset Number of conditions = 4\n";
    const char *axis[] = {"x", "y", "z"};
    for (unsigned int d = 0; d < 3; ++d) // symmetry plane d: id 2 d, component d
      text += "subsection Condition " + std::to_string(d)
              + "\nset Boundary id = " + std::to_string(2 * d)
              + "\nset Type = displacement\nset Components = " + axis[d] + "\nset Value = 0\nend\n";
    text += "subsection Condition 3\nset Boundary id = 5\nset Type = displacement\n"
            "set Components = z\nset Value = -"
            + std::to_string(delta) + " * t\nend\nend\n";
    prm.parse_input_from_string(text);
    geometry::GeometryParameters geometry;
    geometry.parse_parameters(prm, "");
    mechanics::BoundaryConditionParameters bc;
    bc.parse_parameters(prm);
    test_support::Block3dOptions options;
    options.degree = degree;
    options.material.youngs_modulus = E;
    options.material.poissons_ratio = nu;
    options.material.yield_stress = 1e9;
    return std::make_unique<test_support::Block3dProblem>(MPI_COMM_SELF, geometry, bc, options);
  }
} // namespace

// Uniaxial compression by delta = 0.03 of the block of height 3 with one symmetry condition per
// plane: u = (nu eps x, nu eps y, -eps z), eps = delta / 3, is in the Q1 and Q2 spaces, so the
// Newton solution (one linear solve of an elastic system; the second iterate checks the
// residual) is exact up to the round-off of the direct solve: 1e-10 delta. The top reaction is
// -E eps times the top area 2 (1e-10 relative: sums of nodal forces).
TEST(Block3d, SymmetryPlanesUniaxialCompressionIsHomogeneous)
{
  const double delta = 0.03, eps = delta / 3.;
  for (const unsigned int degree : {1u, 2u})
  {
    const auto              problem = block_problem(degree, delta);
    auto                   &b = *problem;
    solver::LinearSolver<3> linear_solver(solver::LinearSolverParameters{});
    for (unsigned int it = 0; it < 2; ++it)
    {
      ASSERT_TRUE(b.assemble().ok);
      TrilinosWrappers::MPI::Vector du(b.u);
      du = 0.;
      linear_solver.solve(b.matrix, du, b.rhs);
      b.newton.distribute(du);
      b.u += du;
    }
    ASSERT_TRUE(b.assemble().ok);

    double error = 0., top_force = 0.;
    for (const test_support::OwnedDof &d : b.owned_dofs())
    {
      const Point<3> &x = d.point;
      const double    exact = d.component < 2 ? nu * eps * x[d.component] : -eps * x[2];
      error = std::max(error, std::abs(b.u[d.index] - exact));
      if (d.component == 2 && std::abs(x[2] - 3.) < 1e-12)
        top_force += b.residual[d.index];
    }
    std::printf("[ block3d ] Q%u: max |u - u_exact| / delta = %.1e, top force %.10g "
                "(exact %.10g)\n",
                degree,
                error / delta,
                top_force,
                -E * eps * 2.);
    EXPECT_LT(error / delta, 1e-10) << "Q" << degree;
    EXPECT_NEAR(top_force, -E * eps * 2., 1e-10 * E * eps * 2.) << "Q" << degree;
  }
}

// Type = automatic: the documented rule (2D: always direct; 3D: iterative from `Automatic
// iterative threshold` unknowns on) in resolved_type(), in the parsed defaults, and in what
// solve() does on a 3D block (direct: 0 iterations; iterative: CG/GMRES + AMG iterations); both
// solutions agree to 1e-7 relative (AMG stops at a relative residual 1e-10, cond(K) ~ 10^2).
TEST(Block3d, AutomaticLinearSolverFollowsThreshold)
{
  {
    ParameterHandler prm;
    solver::SolverParameters::declare_parameters(prm);
    solver::SolverParameters defaults;
    defaults.parse_parameters(prm);
    EXPECT_EQ(defaults.linear.type, solver::LinearSolverType::automatic);
    EXPECT_EQ(defaults.linear.automatic_iterative_threshold, 1e4);
    prm.parse_input_from_string("subsection Solver\nsubsection Linear solver\n"
                                "set Automatic iterative threshold = 500\nend\nend\n");
    solver::SolverParameters changed;
    changed.parse_parameters(prm);
    EXPECT_EQ(changed.linear.automatic_iterative_threshold, 500.);
  }
  solver::LinearSolverParameters p;
  const solver::LinearSolver<2>  two(p);
  const solver::LinearSolver<3>  three(p);
  EXPECT_EQ(two.resolved_type(100000000), solver::LinearSolverType::direct);
  EXPECT_EQ(three.resolved_type(9999), solver::LinearSolverType::direct);
  EXPECT_EQ(three.resolved_type(10000), solver::LinearSolverType::iterative);
  p.type = solver::LinearSolverType::direct;
  EXPECT_EQ(solver::LinearSolver<3>(p).resolved_type(100000000), solver::LinearSolverType::direct);
  p.type = solver::LinearSolverType::iterative;
  EXPECT_EQ(solver::LinearSolver<2>(p).resolved_type(10), solver::LinearSolverType::iterative);

  const auto problem = block_problem(1, 0.03);
  auto      &b = *problem;
  ASSERT_TRUE(b.assemble().ok);
  const unsigned int             n = b.dof_handler.n_dofs();
  solver::LinearSolverParameters below, above;
  below.automatic_iterative_threshold = n + 1;
  above.automatic_iterative_threshold = n;
  solver::LinearSolver<3> direct(below), iterative(above);
  iterative.set_rigid_body_modes(b.dof_handler, b.mapping);
  TrilinosWrappers::MPI::Vector x_direct(b.u), x_iterative(b.u);
  x_direct = 0.;
  x_iterative = 0.;
  const solver::LinearSolveInfo d = direct.solve(b.matrix, x_direct, b.rhs);
  const solver::LinearSolveInfo i = iterative.solve(b.matrix, x_iterative, b.rhs);
  EXPECT_FALSE(d.iterative);
  EXPECT_EQ(d.iterations, 0u);
  EXPECT_TRUE(i.iterative);
  EXPECT_GT(i.iterations, 0u);
  x_iterative -= x_direct;
  std::printf("[ block3d ] automatic: %u DoFs, %u iterations, relative difference %.1e\n",
              n,
              i.iterations,
              x_iterative.l2_norm() / x_direct.l2_norm());
  EXPECT_LT(x_iterative.l2_norm(), 1e-7 * x_direct.l2_norm());
}

// Type = iterative (ML AMG with the rigid-body modes, `PDE equations = 3`; CG for the elastic
// tangent, right-preconditioned GMRES for the unsymmetric F-bar one) on the ranks of
// MPI_COMM_WORLD (the ctest unit/Block3dParallel.mpirun=2 runs this on two, the plain unit run on
// one) against the same system on one rank (MPI_COMM_SELF, on every rank): the systems of
// benchmarks/amg_3d on 12^3 Q1 cells (6591 DoFs, more than ML's coarse size 2000: a multilevel
// hierarchy). Both solves stop at the relative residual 1e-10, so the solutions, compared DoF by
// DoF at equal support point and component, agree to 1e-7 of max |x| (cond(K) ~ 10^3 on this
// mesh); the aggregates do not cross ranks, so the iteration counts may differ, by at most 3 (the
// measured: 10 elastic and 22 F-bar on one rank, 11 and 23 on two, difference 1e-10 of max |x|).
TEST(Block3dParallel, AmgOnAllRanksMatchesOneRank)
{
  const MPI_Comm     world = MPI_COMM_WORLD;
  const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(world);
  for (const std::string mode : {"elastic", "finite"})
  {
    const auto distributed = test_support::compressed_cube(world, mode, 12, 1);
    const auto serial = test_support::compressed_cube(MPI_COMM_SELF, mode, 12, 1);
    ASSERT_TRUE(distributed->assemble().ok);
    ASSERT_TRUE(serial->assemble().ok);

    solver::LinearSolverParameters p;
    p.type = solver::LinearSolverType::iterative;
    p.krylov_method = mode == "elastic" ? solver::KrylovMethod::cg : solver::KrylovMethod::gmres;
    solver::LinearSolver<3> on_all(p), on_one(p);
    on_all.set_rigid_body_modes(distributed->dof_handler, distributed->mapping);
    on_one.set_rigid_body_modes(serial->dof_handler, serial->mapping);
    TrilinosWrappers::MPI::Vector x_all(distributed->rhs), x_one(serial->rhs);
    const solver::LinearSolveInfo all = on_all.solve(distributed->matrix, x_all, distributed->rhs);
    const solver::LinearSolveInfo one = on_one.solve(serial->matrix, x_one, serial->rhs);

    // DoFs are numbered differently on one and on several ranks: match them by support point
    // (multiples of 1/12: keys in units of 1e-9) and component
    const auto key = [](const test_support::OwnedDof &d)
    {
      return std::array<long, 4>{{std::lround(d.point[0] * 1e9),
                                  std::lround(d.point[1] * 1e9),
                                  std::lround(d.point[2] * 1e9),
                                  long(d.component)}};
    };
    std::map<std::array<long, 4>, double> reference;
    double                                x_max = 0.;
    for (const test_support::OwnedDof &d : serial->owned_dofs())
    {
      reference[key(d)] = x_one[d.index];
      x_max = std::max(x_max, std::abs(x_one[d.index]));
    }
    double       difference = 0.;
    unsigned int unmatched = 0;
    for (const test_support::OwnedDof &d : distributed->owned_dofs())
    {
      const auto it = reference.find(key(d));
      if (it == reference.end())
        ++unmatched;
      else
        difference = std::max(difference, std::abs(x_all[d.index] - it->second));
    }
    difference = Utilities::MPI::max(difference, world);
    unmatched = Utilities::MPI::sum(unmatched, world);
    if (Utilities::MPI::this_mpi_process(world) == 0)
      std::printf("[ block3d ] %s, %u DoFs: %u ranks %u iterations, 1 rank %u iterations, max "
                  "difference / max |x| = %.1e\n",
                  mode.c_str(),
                  serial->dof_handler.n_dofs(),
                  n_ranks,
                  all.iterations,
                  one.iterations,
                  difference / x_max);
    EXPECT_TRUE(all.iterative && one.iterative);
    EXPECT_EQ(unmatched, 0u);
    EXPECT_LT(difference, 1e-7 * x_max) << mode;
    EXPECT_LE(std::abs(int(all.iterations) - int(one.iterations)), 3) << mode;
  }
}
