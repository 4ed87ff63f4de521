/**
 * @file test_mechanical_system.cc
 * mechanics::MechanicalSystem in 2D (rectangle) and 3D (`Geometry/Type = block`): DoF counts of
 * FE_Q(1)^dim and FE_Q(2)^dim against the node counts of the structured mesh, the Newton
 * constraints of the symmetry planes and a prescribed top displacement (count and violation),
 * the hanging-node constraints after refining one cell (weights of each line sum to 1, a linear
 * field satisfies them, the transfer of execute_refinement() keeps it exactly), the reaction
 * norm, and the round trip of the step state (commit, predictor, restore, increment).
 * Exact counts; floating-point comparisons to 1e-12 (sums of O(1) weights and interpolation
 * of linear fields by linear/quadratic elements are exact up to round-off).
 */
#include <ausroll/geometry/geometry_parameters.h>
#include <ausroll/geometry/workpiece.h>
#include <ausroll/mechanics/boundary_conditions.h>
#include <ausroll/mechanics/mechanical_system.h>

#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/numerics/vector_tools.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace dealii;
using namespace ausroll;

namespace
{
  /**
   * 2D: rectangle [0, 2] x [0, 3] with 2 x 3 cells (ids 0..3: x_min, x_max, y_min, y_max).
   * 3D: block [0, 2] x [0, 1] x [0, 3] with 2 x 2 x 3 cells (ids 0..5).
   * Symmetry conditions on every lower face (id 2 d, component d) and the top (y = 3 in 2D,
   * z = 3 in 3D) moved by -0.03 t in the last component.
   */
  template <int dim>
  std::string scene_text()
  {
    std::string text = dim == 2 ? "subsection Geometry\nset Type = rectangle\n"
                                  "subsection Rectangle\nset Upper right corner = 2, 3\n"
                                  "set Cells = 2, 3\nend\nend\n"
                                : "subsection Geometry\nset Type = block\nsubsection Block\n"
                                  "set Upper corner = 2, 1, 3\nset Cells = 2, 2, 3\nend\nend\n";
    text += "subsection Boundary conditions\nset Number of conditions = " + std::to_string(dim + 1)
            + "\n";
    const char *axis[] = {"x", "y", "z"};
    for (unsigned int d = 0; d < dim; ++d)
      text += "subsection Condition " + std::to_string(d)
              + "\nset Boundary id = " + std::to_string(2 * d)
              + "\nset Type = displacement\nset Components = " + axis[d] + "\nset Value = 0\nend\n";
    text += "subsection Condition " + std::to_string(dim) + "\nset Boundary id = "
            + std::to_string(2 * dim - 1) + "\nset Type = displacement\nset Components = "
            + axis[dim - 1] + "\nset Value = -0.03 * t\nend\nend\n";
    return text;
  }

  template <int dim>
  struct Fixture
  {
    mechanics::MechanicalSystem<dim>                    system;
    std::unique_ptr<mechanics::BoundaryConditions<dim>> bcs;

    explicit Fixture(const unsigned int degree)
        : system(MPI_COMM_WORLD, degree)
    {
      ParameterHandler prm;
      geometry::GeometryParameters::declare_parameters(prm);
      mechanics::BoundaryConditionParameters::declare_parameters(prm);
      prm.parse_input_from_string(scene_text<dim>());
      geometry::GeometryParameters geometry;
      geometry.parse_parameters(prm, "");
      mechanics::BoundaryConditionParameters bc;
      bc.parse_parameters(prm);
      bcs = std::make_unique<mechanics::BoundaryConditions<dim>>(bc);
      geometry::create_workpiece(geometry, system.triangulation);
      system.setup_system();
      system.initialize_material_points(4);
    }
  };

  /** u(x) = (0.1 x + 0.2 y, 0.3 x - 0.1 y [, 0.05 z]) (+ 0.01 in every component). */
  template <int dim>
  class LinearField : public Function<dim>
  {
  public:
    LinearField()
        : Function<dim>(dim)
    {
    }
    double value(const Point<dim> &p, const unsigned int c) const override
    {
      const double a[3][3] = {{0.1, 0.2, 0.}, {0.3, -0.1, 0.}, {0., 0.02, 0.05}};
      double       v = 0.01;
      for (unsigned int d = 0; d < dim; ++d)
        v += a[c][d] * p[d];
      return v;
    }
  };

  /** Nodes of a structured n_0 x ... mesh of FE_Q(degree): prod (degree n_d + 1). */
  template <int dim>
  unsigned int n_nodes(const unsigned int degree)
  {
    const unsigned int cells[3] = {2, dim == 2 ? 3u : 2u, 3};
    unsigned int       n = 1;
    for (unsigned int d = 0; d < dim; ++d)
      n *= degree * cells[d] + 1;
    return n;
  }

  /** Newton constraints of the symmetry planes and the top: one per node and plane (the planes
      constrain different components, so no DoF twice). */
  template <int dim>
  unsigned int n_plane_constraints(const unsigned int degree)
  {
    const unsigned int cells[3] = {2, dim == 2 ? 3u : 2u, 3};
    unsigned int       total = 0;
    for (unsigned int plane = 0; plane <= dim; ++plane) // planes x_min, y_min, [z_min,] top
    {
      const unsigned int normal = plane < dim ? plane : dim - 1;
      unsigned int       n = 1;
      for (unsigned int d = 0; d < dim; ++d)
        if (d != normal)
          n *= degree * cells[d] + 1;
      total += n;
    }
    return total;
  }

  template <int dim>
  void check_dofs_and_constraints(const unsigned int degree)
  {
    Fixture<dim> f(degree);
    auto        &s = f.system;
    EXPECT_EQ(s.dof_handler.n_dofs(), dim * n_nodes<dim>(degree));
    EXPECT_EQ(s.owned_dofs.n_elements(), s.dof_handler.n_dofs()); // one rank
    EXPECT_EQ(s.hanging_constraints.n_constraints(), 0u);         // uniform mesh
    EXPECT_EQ(s.solution.size(), s.dof_handler.n_dofs());
    // cells of 1 x 1 (2D) and 1 x 0.5 x 1 mm (3D); bounding box 2 x 3 and 2 x 1 x 3
    EXPECT_NEAR(s.min_cell_diameter, dim == 2 ? 1. : 0.5, 1e-12);
    EXPECT_NEAR(s.smallest_extent(), dim == 2 ? 2. : 1., 1e-12);

    // At u = 0 and t = 1 the top constraint asks for -0.03: the violation.
    const double violation = s.build_newton_constraints(*f.bcs, 1.);
    EXPECT_EQ(s.newton_constraints.n_constraints(), n_plane_constraints<dim>(degree));
    EXPECT_NEAR(violation, 0.03, 1e-12);
    // add_more is called and its violation counts
    const double more
        = s.build_newton_constraints(*f.bcs, 1., [](AffineConstraints<double> &) { return 0.5; });
    EXPECT_NEAR(more, 0.5, 1e-15);

    // reaction norm: residual 1 at every DoF -> sqrt(number of Dirichlet DoFs)
    s.residual = 1.;
    EXPECT_NEAR(s.reaction_norm(), std::sqrt(double(n_plane_constraints<dim>(degree))), 1e-12);
  }

  template <int dim>
  void check_hanging_nodes_and_transfer(const unsigned int degree)
  {
    Fixture<dim>           f(degree);
    auto                  &s = f.system;
    const LinearField<dim> field;
    VectorTools::interpolate(s.mapping, s.dof_handler, field, s.solution);
    s.solution_ghosted = s.solution;
    s.system_matrix = 0.; // the old matrix is replaced without trouble
    s.triangulation.begin_active()->set_refine_flag();
    bool attached = false, unpacked = false;
    s.execute_refinement([&]() { attached = true; }, [&]() { unpacked = true; });
    EXPECT_TRUE(attached && unpacked);
    EXPECT_EQ(s.triangulation.n_active_cells(), (dim == 2 ? 6u : 12u) + (1u << dim) - 1u);
    ASSERT_GT(s.hanging_constraints.n_constraints(), 0u);
    for (const auto &line : s.hanging_constraints.get_lines())
    {
      double sum = 0.;
      for (const auto &entry : line.entries)
        sum += entry.second;
      EXPECT_NEAR(sum, 1., 1e-12) << "hanging DoF " << line.index;
      EXPECT_EQ(line.inhomogeneity, 0.);
    }
    // The transferred solution is the interpolant of the linear field on the new mesh.
    Vector<double> reference(s.dof_handler.n_dofs());
    VectorTools::interpolate(s.mapping, s.dof_handler, field, reference);
    double error = 0.;
    for (const auto i : s.owned_dofs)
    {
      error = std::max(error, std::abs(s.solution[i] - reference[i]));
      EXPECT_EQ(s.step_start[i], s.solution[i]);
    }
    EXPECT_LT(error, 1e-12);
  }

  template <int dim>
  void check_step_state_round_trip()
  {
    Fixture<dim> f(1);
    auto        &s = f.system;
    const auto   cell = s.triangulation.begin_active();
    const auto   points = s.material_points.get_data(cell);
    ASSERT_EQ(points.size(), 4u);

    s.solution = 1.; // u_0
    points[0]->trial.equivalent_plastic_strain = 0.5;
    s.commit_step();
    EXPECT_EQ(points[0]->committed.equivalent_plastic_strain, 0.5);
    EXPECT_EQ(s.step_start.linfty_norm(), 1.);
    EXPECT_EQ(s.previous_start.linfty_norm(), 0.);

    s.solution = 2.; // u_1
    s.commit_step();
    EXPECT_EQ(s.previous_start.min(), 1.);
    EXPECT_EQ(s.step_start.min(), 2.);

    s.start_step(0.); // no predictor: u_1
    EXPECT_EQ(s.solution.min(), 2.);
    EXPECT_EQ(s.solution.max(), 2.);
    s.start_step(0.5); // u_1 + 0.5 (u_1 - u_0) = 2.5
    EXPECT_NEAR(s.solution.min(), 2.5, 1e-15);
    EXPECT_NEAR(s.solution.max(), 2.5, 1e-15);
    EXPECT_NEAR(s.solution_ghosted[0], 2.5, 1e-15);

    points[0]->trial.equivalent_plastic_strain = 0.9; // a failed iterate
    s.restore_step_start();
    EXPECT_EQ(s.solution.min(), 2.);
    EXPECT_EQ(s.solution_ghosted[0], 2.);
    EXPECT_EQ(points[0]->trial.equivalent_plastic_strain, 0.5);
    EXPECT_EQ(points[0]->committed.equivalent_plastic_strain, 0.5);

    s.newton_start = s.solution;
    s.increment = 1.;
    s.apply_increment(0.25);
    EXPECT_NEAR(s.solution.min(), 2.25, 1e-15);
    EXPECT_NEAR(s.solution_ghosted[0], 2.25, 1e-15);
  }
} // namespace

TEST(MechanicalSystem2d, DofsAndNewtonConstraintsOfRectangle)
{
  check_dofs_and_constraints<2>(1);
  check_dofs_and_constraints<2>(2);
}

TEST(MechanicalSystem3d, DofsAndNewtonConstraintsOfBlock)
{
  check_dofs_and_constraints<3>(1);
  check_dofs_and_constraints<3>(2);
}

TEST(MechanicalSystem2d, HangingNodesAndTransferOfLinearField)
{
  check_hanging_nodes_and_transfer<2>(1);
  check_hanging_nodes_and_transfer<2>(2);
}

TEST(MechanicalSystem3d, HangingNodesAndTransferOfLinearField)
{
  check_hanging_nodes_and_transfer<3>(1);
  check_hanging_nodes_and_transfer<3>(2);
}

TEST(MechanicalSystem2d, StepStateRoundTrip)
{
  check_step_state_round_trip<2>();
}

TEST(MechanicalSystem3d, StepStateRoundTrip)
{
  check_step_state_round_trip<3>();
}
