/**
 * @file test_block_3d.cc
 * `Geometry/Type = block` with the symmetry planes of `Boundary conditions` in 3D (one component
 * per plane: u_x = 0 on x = 0, u_y = 0 on y = 0, u_z = 0 on z = 0) in uniaxial compression
 * against the homogeneous analytic solution, and the choice of `Solver/Linear solver/Type =
 * automatic` (direct below `Automatic iterative threshold` unknowns in 3D and always in 2D).
 */
#include <ausroll/geometry/geometry_parameters.h>
#include <ausroll/geometry/workpiece.h>
#include <ausroll/material/constitutive_model.h>
#include <ausroll/mechanics/assembler.h>
#include <ausroll/mechanics/boundary_conditions.h>
#include <ausroll/mechanics/planar_kinematics.h>
#include <ausroll/solver/linear_solver.h>
#include <ausroll/solver/solver_parameters.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
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
   * small strain, Q@p degree. assemble() gives the Newton system at the current u.
   */
  struct BlockProblem
  {
    Triangulation<3>                                  tria;
    std::unique_ptr<FESystem<3>>                      fe;
    MappingQ<3>                                       mapping{1};
    DoFHandler<3>                                     dof_handler;
    std::unique_ptr<material::ConstitutiveModel>      model;
    std::unique_ptr<mechanics::BoundaryConditions<3>> bcs;
    mechanics::PlanarKinematics<3>           kinematics{mechanics::PlanarModel::plane_strain, 1.};
    std::unique_ptr<mechanics::Assembler<3>> assembler;
    mechanics::MaterialPointStorage<3>       points;
    TrilinosWrappers::SparseMatrix           matrix;
    TrilinosWrappers::MPI::Vector            u, residual, external, rhs;
    AffineConstraints<double>                newton;

    BlockProblem(const unsigned int degree, const double delta)
    {
      ParameterHandler prm;
      geometry::GeometryParameters::declare_parameters(prm);
      mechanics::BoundaryConditionParameters::declare_parameters(prm);
      std::string text = "subsection Geometry\nset Type = block\nsubsection Block\n"
                         "set Upper corner = 2, 1, 3\nset Cells = 2, 2, 3\nend\nend\n"
                         "subsection Boundary conditions\nset Number of conditions = 4\n";
      const char *axis[] = {"x", "y", "z"};
      for (unsigned int d = 0; d < 3; ++d) // symmetry plane d: id 2 d, component d
        text += "subsection Condition " + std::to_string(d) + "\nset Boundary id = "
                + std::to_string(2 * d) + "\nset Type = displacement\nset Components = " + axis[d]
                + "\nset Value = 0\nend\n";
      text += "subsection Condition 3\nset Boundary id = 5\nset Type = displacement\n"
              "set Components = z\nset Value = -"
              + std::to_string(delta) + " * t\nend\nend\n";
      prm.parse_input_from_string(text);
      geometry::GeometryParameters geometry;
      geometry.parse_parameters(prm, "");
      mechanics::BoundaryConditionParameters bc;
      bc.parse_parameters(prm);

      geometry::create_workpiece(geometry, tria);
      fe = std::make_unique<FESystem<3>>(FE_Q<3>(degree), 3);
      dof_handler.reinit(tria);
      dof_handler.distribute_dofs(*fe);
      material::MaterialParameters mat;
      mat.youngs_modulus = E;
      mat.poissons_ratio = nu;
      mat.yield_stress = 1e9;
      model
          = material::create_constitutive_model(material::KinematicsType::small_strain, mat, false);
      bcs = std::make_unique<mechanics::BoundaryConditions<3>>(bc);
      assembler = std::make_unique<mechanics::Assembler<3>>(
          mapping, *fe, degree + 1, kinematics, *model, *bcs);
      points.initialize(tria.begin_active(), tria.end(), assembler->quadrature().size());

      const IndexSet         all = complete_index_set(dof_handler.n_dofs());
      DynamicSparsityPattern dsp(all);
      DoFTools::make_sparsity_pattern(dof_handler, dsp);
      matrix.reinit(all, all, dsp, MPI_COMM_WORLD);
      for (auto *v : {&u, &residual, &external, &rhs})
        v->reinit(all, MPI_COMM_WORLD);
    }

    /** Newton constraints at t = 1 and the tangent system at u. */
    void assemble()
    {
      newton.clear();
      newton.reinit(complete_index_set(dof_handler.n_dofs()));
      bcs->add_increment_constraints(dof_handler, 1., u, newton);
      newton.close();
      AffineConstraints<double> hanging;
      hanging.close();
      residual = 0.;
      external = 0.;
      matrix = 0.;
      rhs = 0.;
      mechanics::AssemblyTargets targets;
      targets.residual = &residual;
      targets.external_force = &external;
      targets.matrix = &matrix;
      targets.rhs = &rhs;
      ASSERT_TRUE(
          assembler->assemble(dof_handler, u, 1., points, hanging, newton, nullptr, targets).ok);
    }
  };
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
    BlockProblem            b(degree, delta);
    solver::LinearSolver<3> linear_solver(solver::LinearSolverParameters{});
    for (unsigned int it = 0; it < 2; ++it)
    {
      b.assemble();
      TrilinosWrappers::MPI::Vector du(b.u);
      du = 0.;
      linear_solver.solve(b.matrix, du, b.rhs);
      b.newton.distribute(du);
      b.u += du;
    }
    b.assemble();

    std::map<types::global_dof_index, Point<3>> support;
    DoFTools::map_dofs_to_support_points(b.mapping, b.dof_handler, support);
    std::vector<unsigned int>            component(b.dof_handler.n_dofs());
    std::vector<types::global_dof_index> dofs(b.fe->n_dofs_per_cell());
    for (const auto &cell : b.dof_handler.active_cell_iterators())
    {
      cell->get_dof_indices(dofs);
      for (unsigned int i = 0; i < dofs.size(); ++i)
        component[dofs[i]] = b.fe->system_to_component_index(i).first;
    }
    double error = 0., top_force = 0.;
    for (unsigned int i = 0; i < b.dof_handler.n_dofs(); ++i)
    {
      const Point<3> &x = support.at(i);
      const double    exact = component[i] < 2 ? nu * eps * x[component[i]] : -eps * x[2];
      error = std::max(error, std::abs(b.u[i] - exact));
      if (component[i] == 2 && std::abs(x[2] - 3.) < 1e-12)
        top_force += b.residual[i];
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

  BlockProblem b(1, 0.03);
  b.assemble();
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
