/**
 * @file test_boundary_conditions.cc
 * Unit tests of mechanics::BoundaryConditions: parsing of `Boundary conditions`, the Dirichlet
 * increments delta u = g(x, t) - u on the right DoFs only (first condition wins on shared DoFs),
 * surface loads (sums on one boundary, traction = dead traction - p n), the history names, and
 * the InputErrors naming the entry. References are the closed-form expressions (round-off).
 */
#include <ausroll/core/exceptions.h>
#include <ausroll/mechanics/boundary_conditions.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

#include <gtest/gtest.h>

#include <map>
#include <string>

using namespace dealii;
using namespace ausroll::mechanics;

namespace
{
  BoundaryConditionParameters parse(const std::string &conditions)
  {
    ParameterHandler prm;
    BoundaryConditionParameters::declare_parameters(prm);
    prm.parse_input_from_string("subsection Boundary conditions\n" + conditions + "end\n");
    BoundaryConditionParameters p;
    p.parse_parameters(prm);
    return p;
  }

  /** The InputError message of building BoundaryConditions<2> from @p conditions ("" if none). */
  std::string error_of(const std::string &conditions)
  {
    try
    {
      const BoundaryConditions<2> bc(parse(conditions));
    }
    catch (const ausroll::InputError &e)
    {
      return e.what();
    }
    return "";
  }
} // namespace

TEST(BoundaryConditions, DirichletIncrements)
{
  // unit square, Q1, colorized: 0 left, 1 right, 2 bottom, 3 top
  Triangulation<2> tria;
  GridGenerator::subdivided_hyper_cube(tria, 2, 0., 1., true);
  FESystem<2>   fe(FE_Q<2>(1), 2);
  DoFHandler<2> dofs(tria);
  dofs.distribute_dofs(fe);
  const BoundaryConditions<2>   bc(parse(" set Number of conditions = 3\n"
                                         " subsection Condition 0\n  set Boundary id = 2\n"
                                         "  set Type = fixed\n end\n"
                                         " subsection Condition 1\n  set Boundary id = 3\n"
                                         "  set Type = displacement\n  set Components = y\n"
                                         "  set Value = -0.1 * t * (1 + x)\n end\n"
                                         " subsection Condition 2\n  set Boundary id = 0\n"
                                         "  set Type = displacement\n  set Components = x, y\n"
                                         "  set Value = 0.5; 2 * y * t\n end\n"));
  const IndexSet                all = complete_index_set(dofs.n_dofs());
  TrilinosWrappers::MPI::Vector u(all, MPI_COMM_WORLD);
  for (unsigned int i = 0; i < dofs.n_dofs(); ++i)
    u[i] = 0.01 * (i + 1);

  AffineConstraints<double> constraints;
  constraints.reinit(all);
  const double t = 0.5;
  bc.add_increment_constraints(dofs, t, u, constraints);
  constraints.close();

  // support points and components of every DoF
  std::map<types::global_dof_index, Point<2>> points;
  DoFTools::map_dofs_to_support_points(MappingQ1<2>(), dofs, points);
  std::vector<unsigned int> component(dofs.n_dofs());
  {
    std::vector<types::global_dof_index> local(fe.n_dofs_per_cell());
    for (const auto &cell : dofs.active_cell_iterators())
    {
      cell->get_dof_indices(local);
      for (unsigned int i = 0; i < local.size(); ++i)
        component[local[i]] = fe.system_to_component_index(i).first;
    }
  }
  unsigned int n_constrained = 0;
  for (unsigned int i = 0; i < dofs.n_dofs(); ++i)
  {
    const Point<2>    &X = points[i];
    const bool         bottom = X[1]<1e-12, top = X[1]> 1. - 1e-12, left = X[0] < 1e-12;
    const unsigned int c = component[i];
    double             g = 0.;
    bool               constrained = true;
    // the first condition that constrains a DoF wins: fixed at the bottom-left corner, the top
    // condition for y at the top-left corner
    if (bottom)
      g = 0.;
    else if (top && c == 1)
      g = -0.1 * t * (1. + X[0]);
    else if (left)
      g = c == 0 ? 0.5 : 2. * X[1] * t;
    else
      constrained = false;
    EXPECT_EQ(constraints.is_constrained(i), constrained) << "DoF " << i << " at " << X;
    if (constrained)
    {
      ++n_constrained;
      EXPECT_NEAR(constraints.get_inhomogeneity(i), g - u[i], 1e-14) << "DoF " << i << " at " << X;
    }
  }
  // bottom 3 nodes x 2, left 2 more nodes x 2, top 2 more nodes (y only)
  EXPECT_EQ(n_constrained, 3u * 2 + 2 * 2 + 2);

  // DoFs constrained already (contact, hanging nodes) are left alone
  AffineConstraints<double> already;
  already.reinit(all);
  for (unsigned int i = 0; i < dofs.n_dofs(); ++i)
    if (points[i][1] < 1e-12)
    {
      already.add_line(i);
      already.set_inhomogeneity(i, 7.);
    }
  bc.add_increment_constraints(dofs, t, u, already);
  for (unsigned int i = 0; i < dofs.n_dofs(); ++i)
    if (points[i][1] < 1e-12)
      EXPECT_EQ(already.get_inhomogeneity(i), 7.);
}

TEST(BoundaryConditions, SurfaceLoads)
{
  const BoundaryConditions<2> bc(parse(" set Number of conditions = 4\n"
                                       " subsection Condition 0\n  set Boundary id = 1\n"
                                       "  set Type = traction\n  set Value = 3; 2 * x * t\n end\n"
                                       " subsection Condition 1\n  set Boundary id = 1\n"
                                       "  set Type = traction\n  set Value = -1; y\n end\n"
                                       " subsection Condition 2\n  set Boundary id = 1\n"
                                       "  set Type = pressure\n  set Value = 10 * t\n end\n"
                                       " subsection Condition 3\n  set Boundary id = 4\n"
                                       "  set Type = pressure\n  set Value = 5 + sin(pi * t)\n"
                                       " end\n"));
  EXPECT_TRUE(bc.has_surface_load(1));
  EXPECT_TRUE(bc.has_surface_load(4));
  EXPECT_FALSE(bc.has_surface_load(0));
  const Point<2> X(0.3, 0.7);
  const double   t = 0.25;
  const auto     dead = bc.dead_traction(1, X, t);
  EXPECT_NEAR(dead[0], 3. - 1., 1e-14);
  EXPECT_NEAR(dead[1], 2. * 0.3 * t + 0.7, 1e-14);
  EXPECT_NEAR(bc.pressure(1, X, t), 10. * t, 1e-14);
  EXPECT_EQ(bc.pressure(0, X, t), 0.);
  Tensor<1, 2> n;
  n[0] = 0.6;
  n[1] = 0.8;
  const auto total = bc.traction(1, X, n, t);
  EXPECT_NEAR(total[0], dead[0] - 10. * t * 0.6, 1e-14);
  EXPECT_NEAR(total[1], dead[1] - 10. * t * 0.8, 1e-14);
  const auto values = bc.pressure_values(t);
  ASSERT_EQ(values.size(), 2u);
  EXPECT_EQ(values[0].first, "pressure_1");
  EXPECT_NEAR(values[0].second, 10. * t, 1e-14);
  EXPECT_EQ(values[1].first, "pressure_4");
  EXPECT_NEAR(values[1].second, 5. + std::sin(M_PI * t), 1e-14);
}

TEST(BoundaryConditions, InputErrorsNameTheEntry)
{
  const std::string head = " set Number of conditions = 1\n subsection Condition 0\n";
  EXPECT_NE(error_of(head + "  set Type = displacement\n  set Components = z\n end\n")
                .find("Boundary conditions/Condition 0/Components"),
            std::string::npos);
  EXPECT_NE(error_of(head
                     + "  set Type = displacement\n  set Components = x, y\n"
                       "  set Value = 1\n end\n")
                .find("Boundary conditions/Condition 0/Value"),
            std::string::npos);
  EXPECT_NE(error_of(head + "  set Type = traction\n  set Value = 1\n end\n")
                .find("Boundary conditions/Condition 0/Value: needs 2 expressions"),
            std::string::npos);
  EXPECT_NE(error_of(head + "  set Type = pressure\n  set Value = 2 * (t\n end\n")
                .find("Boundary conditions/Condition 0/Value: cannot parse"),
            std::string::npos);
  EXPECT_EQ(error_of(head + "  set Type = pressure\n  set Value = 2 * t\n end\n"), "");
  // a 3D model accepts z
  EXPECT_NO_THROW(BoundaryConditions<3>(
      parse(head + "  set Type = displacement\n  set Components = z\n  set Value = t\n end\n")));
}
