// Unit tests of the floors below contact and Scene instantiated for dim = 3 (issue 14, first
// step): the assembler (patch test; Newton solve of uniaxial compression with the linear
// solver), the linear solver (AMG with six rigid-body modes against the direct solver), the
// material-point transfer and the VTU writer, each against an analytic or exact reference. No
// Scene is involved.
#include "support/assembler_test_problem.h"

#include <ausroll/adaptivity/material_point_transfer.h>
#include <ausroll/io/solution_writer.h>
#include <ausroll/material/constitutive_model.h>
#include <ausroll/mechanics/assembler.h>
#include <ausroll/mechanics/boundary_conditions.h>
#include <ausroll/mechanics/planar_kinematics.h>
#include <ausroll/solver/linear_solver.h>

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>

using namespace dealii;
using namespace ausroll;
using K = material::KinematicsType;
using L = mechanics::VolumetricLocking;

namespace
{
  /** The unit cube in 2 x 2 x 2 cells, boundary ids 0..5 on x = 0, 1, y = 0, 1, z = 0, 1;
      the interior vertex moved by @p shift (the cells become general trilinear hexahedra). */
  void make_cube(Triangulation<3> &tria, const unsigned int n, const Tensor<1, 3> &shift = {})
  {
    GridGenerator::subdivided_hyper_rectangle(
        tria, {n, n, n}, Point<3>(0., 0., 0.), Point<3>(1., 1., 1.), /*colorize=*/true);
    for (auto &cell : tria.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        if (cell->vertex(v).distance(Point<3>(0.5, 0.5, 0.5)) < 1e-12)
          cell->vertex(v) = Point<3>(0.5, 0.5, 0.5) + shift;
  }

  /** Component and support point of every DoF. */
  void dof_points(const Mapping<3>                            &mapping,
                  const DoFHandler<3>                         &dof_handler,
                  std::vector<unsigned int>                   &component,
                  std::map<types::global_dof_index, Point<3>> &points)
  {
    DoFTools::map_dofs_to_support_points(mapping, dof_handler, points);
    component.assign(dof_handler.n_dofs(), 0);
    std::vector<types::global_dof_index> dofs(dof_handler.get_fe().n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
    {
      cell->get_dof_indices(dofs);
      for (unsigned int i = 0; i < dofs.size(); ++i)
        component[dofs[i]] = dof_handler.get_fe().system_to_component_index(i).first;
    }
  }

  material::MaterialParameters elastic_material()
  {
    material::MaterialParameters mat;
    mat.youngs_modulus = 1000.;
    mat.poissons_ratio = 0.3;
    mat.yield_stress = 1e9; // never yields
    return mat;
  }

  std::string name(const K k)
  {
    return material::to_string(k);
  }
} // namespace

// (a) Patch test. For u = H X (affine) every model gives one constant P = P(I + H). Then the
// internal force is f_i = int P : Grad phi_i dV = int_(dOmega) (P N) . phi_i dA: zero at interior
// DoFs, and at boundary DoFs the nodal reaction of the traction P N = sigma n da / dA. On trilinear
// hexahedra (distorted interior vertex) Gauss(k+1) integrates cof(J) Grad phi exactly for Q1 and
// Q2, so the identity holds to round-off: tolerance 1e-11 of max |f| (sums of ~10^2 terms).
TEST(Dim3, PatchTestAffineDisplacementGivesFaceReactionsOnly)
{
  Tensor<2, 3> H_large;
  const double h[3][3] = {{0.1, 0.05, -0.02}, {0.03, -0.08, 0.04}, {-0.05, 0.02, 0.12}};
  for (unsigned int i = 0; i < 3; ++i)
    for (unsigned int j = 0; j < 3; ++j)
      H_large[i][j] = h[i][j];

  for (const unsigned int degree : {1u, 2u})
    for (const K kin :
         {K::small_strain, K::total_lagrangian, K::updated_lagrangian, K::finite_strain})
      for (const L locking : {L::none, L::f_bar})
      {
        test_support::AssemblerTestOptions options;
        options.degree = degree;
        options.kinematics = kin;
        options.material = elastic_material();
        options.locking = locking;
        test_support::AssemblerTestProblem<3> problem(
            options,
            [](Triangulation<3> &tria) {
              make_cube(tria, 2, Tensor<1, 3>({0.06, -0.04, 0.05}));
            });
        const FESystem<3>                   &fe = problem.fe;
        const MappingQ<3>                   &mapping = problem.mapping;
        const DoFHandler<3>                 &dof_handler = problem.dof_handler;
        const unsigned int                   n = problem.n_dofs();
        const TrilinosWrappers::MPI::Vector &residual = problem.residual;

        const Tensor<2, 3> H = kin == K::small_strain ? Tensor<2, 3>(0.01 * H_large) : H_large;
        std::vector<unsigned int>                   component;
        std::map<types::global_dof_index, Point<3>> support;
        dof_points(mapping, dof_handler, component, support);
        for (unsigned int i = 0; i < n; ++i)
          problem.u[i] = (H * support[i])[component[i]];

        const auto status = problem.assemble(problem.u, false);
        ASSERT_TRUE(status.ok) << status.message;

        // reference: the nodal forces of the traction P N on the six faces
        Tensor<2, 3> F = H;
        for (unsigned int d = 0; d < 3; ++d)
          F[d][d] += 1.;
        material::MaterialState trial;
        Tensor<2, 3>            P;
        problem.model->evaluate(F, material::MaterialState(), trial, P, nullptr);
        Vector<double>                       reference(n);
        FEFaceValues<3>                      fe_face(mapping,
                                fe,
                                QGauss<2>(degree + 1),
                                update_values | update_normal_vectors | update_JxW_values);
        std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
        for (const auto &cell : dof_handler.active_cell_iterators())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary())
            {
              fe_face.reinit(cell, face);
              cell->get_dof_indices(dofs);
              for (unsigned int q = 0; q < fe_face.n_quadrature_points; ++q)
              {
                const Tensor<1, 3> t = P * fe_face.normal_vector(q);
                for (unsigned int i = 0; i < dofs.size(); ++i)
                {
                  const unsigned int c = fe.system_to_component_index(i).first;
                  reference[dofs[i]]
                      += t[c] * fe_face.shape_value_component(i, q, c) * fe_face.JxW(q);
                }
              }
            }

        const IndexSet boundary = DoFTools::extract_boundary_dofs(dof_handler);
        double         scale = 0., interior = 0., reaction = 0.;
        for (unsigned int i = 0; i < n; ++i)
        {
          scale = std::max(scale, std::abs(reference[i]));
          if (boundary.is_element(i))
            reaction = std::max(reaction, std::abs(residual[i] - reference[i]));
          else
            interior = std::max(interior, std::abs(residual[i]));
        }
        ASSERT_GT(scale, 0.);
        std::printf("[ dim3 ] patch Q%u %-20s %-6s interior %.1e reactions %.1e (of %.2e)\n",
                    degree,
                    name(kin).c_str(),
                    locking == L::f_bar ? "F-bar" : "",
                    interior / scale,
                    reaction / scale,
                    scale);
        EXPECT_LT(interior / scale, 1e-11) << "Q" << degree << " " << name(kin);
        EXPECT_LT(reaction / scale, 1e-11) << "Q" << degree << " " << name(kin);
      }
}

namespace
{
  /**
   * Uniaxial compression of the unit cube (2 x 2 x 2 Q1 cells, small strain): symmetry planes
   * x = 0, y = 0, z = 0, top z = 1 moved by -delta in @p n_steps steps, Newton with the
   * Assembler<3> and the direct LinearSolver<3>. Returns the displacement; points hold the states.
   */
  struct UniaxialResult
  {
    std::vector<double>                         u;
    std::vector<unsigned int>                   component;
    std::map<types::global_dof_index, Point<3>> support;
    std::vector<material::MaterialState>        states;
  };

  UniaxialResult uniaxial_compression(const material::MaterialParameters &mat,
                                      const double                        delta,
                                      const unsigned int                  n_steps)
  {
    test_support::AssemblerTestOptions options;
    options.material = mat;
    test_support::AssemblerTestProblem<3> problem(
        options, [](Triangulation<3> &tria) { make_cube(tria, 2); });
    const FESystem<3>             &fe = problem.fe;
    const MappingQ<3>             &mapping = problem.mapping;
    const DoFHandler<3>           &dof_handler = problem.dof_handler;
    const unsigned int             n = problem.n_dofs();
    TrilinosWrappers::MPI::Vector &u = problem.u;
    TrilinosWrappers::MPI::Vector  du = problem.vector();
    solver::LinearSolver<3>        linear_solver(solver::LinearSolverParameters{});

    const double force_scale = mat.youngs_modulus.value(0.) * delta; // stress x unit area
    for (unsigned int step = 1; step <= n_steps; ++step)
    {
      bool converged = false;
      for (unsigned int it = 0; it < 15 && !converged; ++it)
      {
        // increment constraints: symmetry planes fixed, the top moves to its target in the first
        // iteration of the step
        AffineConstraints<double> newton;
        for (unsigned int c = 0; c < 3; ++c)
          VectorTools::interpolate_boundary_values(
              mapping,
              dof_handler,
              2 * c,
              Functions::ZeroFunction<3>(3),
              newton,
              fe.component_mask(FEValuesExtractors::Scalar(c)));
        VectorTools::interpolate_boundary_values(
            mapping,
            dof_handler,
            5,
            Functions::ConstantFunction<3>(it == 0 ? -delta / n_steps : 0., 3),
            newton,
            fe.component_mask(FEValuesExtractors::Scalar(2)));
        newton.close();

        const auto status = problem.assemble(u, problem.targets(true), &newton);
        EXPECT_TRUE(status.ok) << status.message;
        if (it > 0 && problem.rhs.l2_norm() < 1e-12 * force_scale)
        {
          converged = true;
          break;
        }
        du = 0.;
        linear_solver.solve(problem.matrix, du, problem.rhs);
        newton.distribute(du);
        u += du;
      }
      EXPECT_TRUE(converged) << "step " << step;
      for (const auto &cell : problem.tria.active_cell_iterators())
        for (const auto &p : problem.points.get_data(cell))
          p->commit();
    }

    UniaxialResult result;
    for (unsigned int i = 0; i < n; ++i)
      result.u.push_back(u[i]);
    dof_points(mapping, dof_handler, result.component, result.support);
    for (const auto &cell : problem.tria.active_cell_iterators())
      for (const auto &p : problem.points.get_data(cell))
        result.states.push_back(p->committed);
    return result;
  }
} // namespace

// (b) Uniaxial compression with symmetry conditions. Elastic: u = (nu delta x, nu delta y,
// -delta z) is in the Q1 space, so the discrete solution is exact: tolerance 1e-12 delta (the
// direct solve of a well-conditioned 81-DoF system, Newton converged to 1e-12 E delta).
// J2 with linear hardening: the homogeneous state has sigma_zz = -(sigma_y + H eps_p),
// eps_p = (delta - sigma_y / E) / (1 + H / E), lateral strain nu sigma / E + eps_p / 2: tolerance
// 1e-9 relative (Newton tolerance 1e-12 E delta on the residual).
TEST(Dim3, UniaxialCompressionNewtonSolveMatchesAnalyticSolution)
{
  const double delta = 0.01;
  {
    const material::MaterialParameters mat = elastic_material();
    const UniaxialResult               r = uniaxial_compression(mat, delta, 1);
    double                             error = 0.;
    for (unsigned int i = 0; i < r.u.size(); ++i)
    {
      const Point<3> &x = r.support.at(i);
      const double    exact = r.component[i] < 2
                                  ? mat.poissons_ratio.value(0.) * delta * x[r.component[i]]
                                  : -delta * x[2];
      error = std::max(error, std::abs(r.u[i] - exact));
    }
    std::printf("[ dim3 ] uniaxial elastic: max |u - u_exact| / delta = %.1e\n", error / delta);
    EXPECT_LT(error / delta, 1e-12);
  }
  {
    material::MaterialParameters mat = elastic_material();
    mat.yield_stress = 2.; // yield strain 0.002 < delta
    mat.hardening_modulus = 50.;
    const UniaxialResult r = uniaxial_compression(mat, delta, 2);
    const double         E = mat.youngs_modulus.value(0.), s_y = mat.yield_stress.value(0.),
                 H = mat.hardening_modulus.value(0.);
    const double eps_p = (delta - s_y / E) / (1. + H / E);
    const double sigma = s_y + H * eps_p;
    double       stress_error = 0., eps_p_error = 0.;
    for (const auto &state : r.states)
    {
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          stress_error = std::max(stress_error,
                                  std::abs(state.stress[i][j] - (i == 2 && j == 2 ? -sigma : 0.)));
      eps_p_error = std::max(eps_p_error, std::abs(state.equivalent_plastic_strain - eps_p));
    }
    const double lateral = mat.poissons_ratio.value(0.) * sigma / E + 0.5 * eps_p;
    double       u_error = 0.;
    for (unsigned int i = 0; i < r.u.size(); ++i)
    {
      const Point<3> &x = r.support.at(i);
      const double    exact = r.component[i] < 2 ? lateral * x[r.component[i]] : -delta * x[2];
      u_error = std::max(u_error, std::abs(r.u[i] - exact));
    }
    std::printf("[ dim3 ] uniaxial J2: sigma = %.6f, |sigma - exact| / sigma_y = %.1e, "
                "|eps_p - exact| / eps_p = %.1e, |u - exact| / delta = %.1e\n",
                sigma,
                stress_error / s_y,
                eps_p_error / eps_p,
                u_error / delta);
    EXPECT_GT(eps_p, 0.);
    EXPECT_LT(stress_error / s_y, 1e-9);
    EXPECT_LT(eps_p_error / eps_p, 1e-9);
    EXPECT_LT(u_error / delta, 1e-9);
  }
}

// (c) LinearSolver<3>: CG + ML AMG with the six rigid-body modes against the direct solver on a
// clamped 12 x 12 x 12 Q1 elastic block with a surface traction. The iterative solution stops at a
// relative residual of 1e-10, so its error is at most cond(K) 1e-10 (cond ~ 10^3 for this mesh):
// tolerance 1e-6 relative. The modes span the kernel of the unconstrained small-strain stiffness:
// |K m| <= 1e-10 |K|_F |m| (round-off of the assembly).
TEST(Dim3, AlgebraicMultigridWithSixRigidBodyModesMatchesDirectSolver)
{
  test_support::AssemblerTestOptions options;
  options.material = elastic_material();
  options.conditions = {test_support::surface_load(
      5, mechanics::BoundaryConditionType::traction, "0.5 * x; -0.3; -1 - y")};
  test_support::AssemblerTestProblem<3> problem(
      options, [](Triangulation<3> &tria) { make_cube(tria, 12); });
  const MappingQ<3>                    &mapping = problem.mapping;
  const DoFHandler<3>                  &dof_handler = problem.dof_handler;
  const unsigned int                    n = problem.n_dofs();
  const IndexSet                       &all = problem.all;
  const TrilinosWrappers::SparseMatrix &matrix = problem.matrix;
  const TrilinosWrappers::MPI::Vector  &rhs = problem.rhs;
  TrilinosWrappers::SparseMatrix        free_matrix = problem.new_matrix();
  TrilinosWrappers::MPI::Vector         free_rhs = problem.vector();

  AffineConstraints<double> clamped;
  VectorTools::interpolate_boundary_values(
      mapping, dof_handler, 4, Functions::ZeroFunction<3>(3), clamped);
  clamped.close();

  mechanics::AssemblyTargets free_targets = problem.targets(true);
  free_targets.matrix = &free_matrix;
  free_targets.rhs = &free_rhs;
  ASSERT_TRUE(problem.assemble(problem.u, problem.targets(true), &clamped).ok);
  ASSERT_TRUE(problem.assemble(problem.u, free_targets).ok);
  ASSERT_GT(rhs.l2_norm(), 0.);

  solver::LinearSolverParameters direct_parameters, amg_parameters;
  amg_parameters.type = solver::LinearSolverType::iterative;
  amg_parameters.krylov_method = solver::KrylovMethod::cg;
  solver::LinearSolver<3> direct(direct_parameters), amg(amg_parameters);
  amg.set_rigid_body_modes(dof_handler, mapping);

  TrilinosWrappers::MPI::Vector x_direct(all, MPI_COMM_WORLD), x_amg(all, MPI_COMM_WORLD);
  direct.solve(matrix, x_direct, rhs);
  const solver::LinearSolveInfo info = amg.solve(matrix, x_amg, rhs);
  TrilinosWrappers::MPI::Vector difference = x_amg;
  difference -= x_direct;
  const double relative = difference.l2_norm() / x_direct.l2_norm();
  std::printf(
      "[ dim3 ] AMG (6 modes) vs direct, %u DoFs: %u CG iterations, relative difference %.1e\n",
      n,
      info.iterations,
      relative);
  EXPECT_LT(relative, 1e-6);
  EXPECT_GT(info.iterations, 0u);
  EXPECT_LT(info.iterations, 100u);
  // the modes reach ML: without them (ML's default null space) CG needs more iterations
  solver::LinearSolver<3>       amg_without_modes(amg_parameters);
  TrilinosWrappers::MPI::Vector x_plain(all, MPI_COMM_WORLD);
  const unsigned int plain_iterations = amg_without_modes.solve(matrix, x_plain, rhs).iterations;
  std::printf("[ dim3 ] AMG without rigid-body modes: %u CG iterations\n", plain_iterations);
  EXPECT_LT(info.iterations, plain_iterations);

  // the six modes: independent, and in the kernel of the unconstrained stiffness
  const auto &modes = amg.get_rigid_body_modes();
  ASSERT_EQ(modes.size(), 6u);
  const double       norm_K = free_matrix.frobenius_norm();
  FullMatrix<double> gram(6, 6);
  for (unsigned int m = 0; m < 6; ++m)
  {
    ASSERT_EQ(modes[m].size(), n);
    TrilinosWrappers::MPI::Vector v(all, MPI_COMM_WORLD), Kv(all, MPI_COMM_WORLD);
    for (unsigned int i = 0; i < n; ++i)
      v[i] = modes[m][i];
    free_matrix.vmult(Kv, v);
    const double ratio = Kv.l2_norm() / (norm_K * v.l2_norm());
    std::printf("[ dim3 ] rigid-body mode %u: |K m| / (|K| |m|) = %.1e\n", m, ratio);
    EXPECT_LT(ratio, 1e-10) << "mode " << m;
    for (unsigned int k = 0; k < 6; ++k)
      for (unsigned int i = 0; i < n; ++i)
        gram(m, k) += modes[m][i] * modes[k][i];
  }
  // linearly independent: the Gram matrix is regular (its determinant relative to the product of
  // its diagonal is far from 0; for orthogonal modes it is 1)
  double diagonal = 1.;
  for (unsigned int m = 0; m < 6; ++m)
    diagonal *= gram(m, m);
  EXPECT_GT(gram.determinant() / diagonal, 1e-3);
}

// (d) MaterialPointTransfer<3>: a constant state (every packed value non-zero) survives
// refinement of one cell and coarsening back, for both methods. Nearest point copies and
// averages equal values; the polynomial fit reproduces constants up to the round-off of the
// least-squares solve (8 x 8 normal equations): tolerance 1e-12 relative.
TEST(Dim3, MaterialPointTransferKeepsConstantStateThroughRefineAndCoarsen)
{
  material::MaterialState constant;
  for (unsigned int i = 0; i < 3; ++i)
    for (unsigned int j = i; j < 3; ++j)
    {
      constant.stress[i][j] = 100. + 10. * i - 7. * j;
      constant.plastic_strain[i][j] = 0.01 * (1. + i + j);
      constant.back_stress[i][j] = 3. - i + 0.5 * j;
      constant.elastic_left_cauchy_green[i][j] = (i == j ? 1.1 : 0.03 * (i + j));
    }
  for (unsigned int i = 0; i < 3; ++i)
    for (unsigned int j = 0; j < 3; ++j)
      constant.deformation_gradient[i][j] = (i == j ? 1.05 : 0.02 * (i + 2. * j + 1.));
  constant.equivalent_plastic_strain = 0.123;
  std::vector<double> expected;
  constant.pack(expected);

  for (const auto method :
       {adaptivity::TransferMethod::nearest_point, adaptivity::TransferMethod::polynomial})
  {
    parallel::distributed::Triangulation<3> tria(MPI_COMM_WORLD);
    GridGenerator::hyper_cube(tria, 0., 1.);
    tria.refine_global(1);
    const QGauss<3>                    quadrature(2);
    mechanics::MaterialPointStorage<3> storage;
    storage.initialize(tria.begin_active(), tria.end(), quadrature.size());
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto &p : storage.get_data(cell))
        p->committed = p->trial = constant;

    adaptivity::MaterialPointTransfer<3> transfer(tria, storage, quadrature, method, {});
    auto                                 remesh = [&]()
    {
      tria.prepare_coarsening_and_refinement();
      transfer.prepare();
      tria.execute_coarsening_and_refinement();
      transfer.unpack();
    };
    tria.begin_active()->set_refine_flag();
    remesh();
    ASSERT_EQ(tria.n_active_cells(), 15u);
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->level() == 2)
        cell->set_coarsen_flag();
    remesh();
    ASSERT_EQ(tria.n_active_cells(), 8u);

    double error = 0.;
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto &p : storage.get_data(cell))
      {
        std::vector<double> values;
        p->committed.pack(values);
        for (unsigned int k = 0; k < values.size(); ++k)
          error = std::max(error, std::abs(values[k] - expected[k]) / std::abs(expected[k]));
      }
    std::printf("[ dim3 ] transfer %s: max relative change %.1e\n",
                method == adaptivity::TransferMethod::polynomial ? "polynomial" : "nearest point",
                error);
    EXPECT_LT(error, 1e-12);
  }
}

// SolutionWriter<3>: a 2 x 2 x 2 Q1 block is written as 8 hexahedral patches (8 x 8 points, no
// points shared between patches) with a 3-component displacement and a cell field, and the .pvd
// record lists the step (exact counts, no tolerance).
TEST(Dim3, SolutionWriterWritesHexahedraWithThreeComponentDisplacement)
{
  parallel::distributed::Triangulation<3> tria(MPI_COMM_WORLD);
  make_cube(tria, 2);
  const FESystem<3> fe(FE_Q<3>(1), 3);
  const MappingQ<3> mapping(1);
  DoFHandler<3>     dof_handler(tria);
  dof_handler.distribute_dofs(fe);
  const IndexSet                all = complete_index_set(dof_handler.n_dofs());
  TrilinosWrappers::MPI::Vector u(all, MPI_COMM_WORLD);
  for (unsigned int i = 0; i < dof_handler.n_dofs(); ++i)
    u[i] = 0.01 * i;

  const std::filesystem::path directory = std::filesystem::temp_directory_path()
                                          / ("ausroll_dim3_writer_" + std::to_string(::getpid()));
  std::filesystem::create_directories(directory);
  io::SolutionWriter<3>            writer(directory.string(), MPI_COMM_WORLD);
  const std::vector<io::CellField> cells{{"cell_field", Vector<float>(tria.n_active_cells())}};
  writer.write(3, 0.5, dof_handler, mapping, u, cells, {}, true);

  std::string vtu;
  for (const auto &entry : std::filesystem::directory_iterator(directory))
    if (entry.path().extension() == ".vtu")
    {
      std::ifstream in(entry.path());
      vtu.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
  std::ifstream     pvd_file(directory / "solution.pvd");
  const std::string pvd((std::istreambuf_iterator<char>(pvd_file)),
                        std::istreambuf_iterator<char>());
  std::filesystem::remove_all(directory);

  ASSERT_FALSE(vtu.empty());
  EXPECT_NE(vtu.find("NumberOfPoints=\"64\""), std::string::npos);
  EXPECT_NE(vtu.find("NumberOfCells=\"8\""), std::string::npos);
  EXPECT_NE(vtu.find("Name=\"displacement\" NumberOfComponents=\"3\""), std::string::npos);
  EXPECT_NE(vtu.find("Name=\"cell_field\""), std::string::npos);
  EXPECT_NE(pvd.find("timestep=\"0.5\""), std::string::npos);
}
