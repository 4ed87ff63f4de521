// Unit tests of the postprocessor interface (io/postprocess/interface.h) on a 4 x 2 cell bar in
// uniaxial stress: the reaction column against sigma A, a monitor displacement against the
// prescribed linear field, the fixed column order, and a duplicate column name as an internal
// error.
#include <ausroll/contact/contact_operator.h>
#include <ausroll/io/postprocess/interface.h>
#include <ausroll/io/postprocess/material_state.h>
#include <ausroll/io/postprocess/monitor_points.h>
#include <ausroll/io/postprocess/reaction_forces.h>
#include <ausroll/io/postprocess/stage.h>
#include <ausroll/io/postprocess/standard_set.h>
#include <ausroll/io/postprocess/step_statistics.h>
#include <ausroll/material/constitutive_model.h>
#include <ausroll/mechanics/assembler.h>
#include <ausroll/mechanics/boundary_conditions.h>
#include <ausroll/mechanics/planar_kinematics.h>

#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/numerics/vector_tools.h>

#include <gtest/gtest.h>

#include <stdexcept>

using namespace dealii;
using namespace ausroll;

namespace
{
  constexpr double L = 2., H = 1., E = 1000., nu = 0.3, eps = 1e-3; ///< bar and load

  /** u_x = eps x, u_y = -nu / (1 - nu) eps y. */
  class UniaxialField : public Function<2>
  {
  public:
    UniaxialField()
        : Function<2>(2)
    {
    }
    double value(const Point<2> &p, const unsigned int c) const override
    {
      return c == 0 ? eps * p[0] : -nu / (1. - nu) * eps * p[1];
    }
  };

  /**
   * The bar [0, L] x [0, H] (L = 2, H = 1, 4 x 2 Q1 cells, colorized: x = L is boundary 1, x = 0
   * boundary 0), linear elastic, small strain, plane strain, thickness 1, displaced by the
   * uniaxial-stress field u_x = eps x, u_y = -nu / (1 - nu) eps y: sigma_xx = E / (1 - nu^2) eps,
   * all other in-plane stresses zero, so the supports at x = L pull with sigma_xx H (x) and 0 (y).
   * The residual f_int of the real assembler is what the scene hands to the postprocessors.
   */
  struct Bar
  {
    Triangulation<2>                             tria;
    FESystem<2>                                  fe{FE_Q<2>(1), 2};
    MappingQ<2>                                  mapping{1};
    DoFHandler<2>                                dof_handler;
    std::unique_ptr<material::ConstitutiveModel> model;
    mechanics::BoundaryConditions<2>             bcs{mechanics::BoundaryConditionParameters()};
    mechanics::PlanarKinematics<2>     kinematics{mechanics::PlanarModel::plane_strain, 1.};
    mechanics::MaterialPointStorage<2> points;
    contact::ContactOperator<2>        contact{contact::ContactParameters()};
    TrilinosWrappers::MPI::Vector      u, residual, external;

    Bar()
    {
      GridGenerator::subdivided_hyper_rectangle(
          tria, {4, 2}, Point<2>(0., 0.), Point<2>(L, H), /*colorize=*/true);
      dof_handler.reinit(tria);
      dof_handler.distribute_dofs(fe);
      material::MaterialParameters mat;
      mat.youngs_modulus = E;
      mat.poissons_ratio = nu;
      mat.yield_stress = 1e9;
      model
          = material::create_constitutive_model(material::KinematicsType::small_strain, mat, false);
      const mechanics::Assembler<2> assembler(
          mapping, fe, 2, kinematics, *model, bcs, mechanics::VolumetricLocking::none);
      points.initialize(tria.begin_active(), tria.end(), assembler.quadrature().size());

      const IndexSet all = complete_index_set(dof_handler.n_dofs());
      u.reinit(all, MPI_COMM_SELF);
      residual.reinit(all, MPI_COMM_SELF);
      external.reinit(all, MPI_COMM_SELF);
      VectorTools::interpolate(mapping, dof_handler, UniaxialField(), u);
      AffineConstraints<double> none;
      none.close();
      mechanics::AssemblyTargets targets;
      targets.residual = &residual;
      targets.external_force = &external;
      const auto status
          = assembler.assemble(dof_handler, u, 1., points, none, none, nullptr, targets);
      EXPECT_TRUE(status.ok) << status.message;
      for (const auto &cell : tria.active_cell_iterators())
        for (const auto &p : points.get_data(cell))
          p->commit();
    }

    io::PostprocessInput<2> input() const
    {
      io::PostprocessInput<2> in{mapping, dof_handler, u, residual, points, *model, bcs, contact};
      in.time = 0.5;
      in.step = 3;
      in.newton_iterations = 2;
      in.cutbacks = 1;
      return in;
    }
  };

  double value(const io::HistoryRow &row, const std::string &name)
  {
    unsigned int found = 0;
    double       v = 0.;
    for (const auto &[n, x] : row)
      if (n == name)
      {
        ++found;
        v = x;
      }
    EXPECT_EQ(found, 1u) << name;
    return v;
  }
} // namespace

TEST(PostprocessorSet, ReactionOfUniaxialBarIsSigmaTimesArea)
{
  Bar                     bar;
  io::PostprocessorSet<2> set(io::OutputParameters(), MPI_COMM_SELF);
  set.add(std::make_unique<io::postprocess::StepStatistics<2>>(2.));
  set.add(std::make_unique<io::postprocess::MonitorPoints<2>>("tip: 1.5, 0.5"));
  set.add(std::make_unique<io::postprocess::ReactionForces<2>>(std::vector<unsigned int>{1, 0}));
  set.add(std::make_unique<io::postprocess::YieldExcess<2>>(1e9));
  set.initialize(bar.input());
  const io::HistoryRow row = set.history_row(bar.input());

  // Fixed order: the postprocessors' columns in the order they were added.
  const std::vector<std::string> expected{"step",
                                          "time",
                                          "load_factor",
                                          "newton_iterations",
                                          "cutbacks",
                                          "dofs",
                                          "cells",
                                          "wall_seconds",
                                          "tip_ux",
                                          "tip_uy",
                                          "reaction_1_x",
                                          "reaction_1_y",
                                          "reaction_0_x",
                                          "reaction_0_y",
                                          "yield_excess"};
  ASSERT_EQ(row.size(), expected.size());
  for (unsigned int i = 0; i < row.size(); ++i)
    EXPECT_EQ(row[i].first, expected[i]);

  EXPECT_EQ(value(row, "step"), 3.);
  EXPECT_EQ(value(row, "load_factor"), 0.25);
  EXPECT_EQ(value(row, "cells"), 8.);
  EXPECT_EQ(value(row, "dofs"), 30.);
  // Q1 reproduces the linear field at any point: round-off only.
  EXPECT_NEAR(value(row, "tip_ux"), eps * 1.5, 1e-15);
  EXPECT_NEAR(value(row, "tip_uy"), -nu / (1. - nu) * eps * 0.5, 1e-15);
  // Uniform stress is exact for Q1 and the Gauss rule: sigma A up to round-off (1e-12 relative).
  const double sigma_A = E / (1. - nu * nu) * eps * H;
  EXPECT_NEAR(value(row, "reaction_1_x"), sigma_A, 1e-12 * sigma_A);
  EXPECT_NEAR(value(row, "reaction_1_y"), 0., 1e-12 * sigma_A);
  EXPECT_NEAR(value(row, "reaction_0_x"), -sigma_A, 1e-12 * sigma_A);
  EXPECT_NEAR(value(row, "reaction_0_y"), 0., 1e-12 * sigma_A);
  EXPECT_EQ(value(row, "yield_excess"), 0.); // elastic: far from the yield surface
}

TEST(PostprocessorSet, DuplicateColumnIsAnInternalError)
{
  Bar                     bar;
  io::PostprocessorSet<2> set(io::OutputParameters(), MPI_COMM_SELF);
  set.add(std::make_unique<io::postprocess::ReactionForces<2>>(std::vector<unsigned int>{1}));
  set.add(std::make_unique<io::postprocess::StepStatistics<2>>(1.));
  set.add(std::make_unique<io::postprocess::ReactionForces<2>>(std::vector<unsigned int>{0, 1}));
  set.initialize(bar.input());
  try
  {
    set.history_row(bar.input());
    FAIL() << "a duplicate column was accepted";
  }
  catch (const std::logic_error &e)
  {
    const std::string what = e.what();
    EXPECT_NE(what.find("'reaction_1_x'"), std::string::npos) << what;
    EXPECT_NE(what.find("reaction forces"), std::string::npos) << what;
  }

  // Also within one postprocessor (the same boundary listed twice).
  io::PostprocessorSet<2> twice(io::OutputParameters(), MPI_COMM_SELF);
  twice.add(std::make_unique<io::postprocess::ReactionForces<2>>(std::vector<unsigned int>{0, 0}));
  twice.initialize(bar.input());
  EXPECT_THROW(twice.history_row(bar.input()), std::logic_error);
}

// The registered postprocessors in the order of the lines of make_standard_postprocessors() before
// the registry (part of the output format: a change reorders every history.csv), the temperature,
// phase and stage postprocessors last and only in runs that have them; 2D and 3D alike.
TEST(PostprocessorRegistry, StandardSetKeepsTheColumnOrder)
{
  const io::OutputParameters      output;
  const io::PostprocessParameters postprocess;
  for (const bool thermal : {false, true})
  {
    io::PostprocessorContext context{output, postprocess, 1., 100., 2, thermal, thermal};
    if (thermal)
      context.stage_end_times = {0.5, 1.};
    std::vector<std::string> expected{"step statistics",
                                      "applied pressures",
                                      "monitor points",
                                      "reaction forces",
                                      "die forces",
                                      "yield excess",
                                      "line probes",
                                      "boundary profile",
                                      "contact nodes",
                                      "cell averages",
                                      "die geometry"};
    if (thermal)
      expected.insert(expected.end(), {"temperature", "phases", "stage"});
    const auto               set_2d = io::make_standard_postprocessors<2>(context, MPI_COMM_SELF);
    const auto               set_3d = io::make_standard_postprocessors<3>(context, MPI_COMM_SELF);
    std::vector<std::string> names_2d, names_3d;
    for (const auto &p : set_2d->postprocessors())
      names_2d.push_back(p->name());
    for (const auto &p : set_3d->postprocessors())
      names_3d.push_back(p->name());
    EXPECT_EQ(names_2d, expected);
    EXPECT_EQ(names_3d, expected);
  }
}

// The stage column: the stage whose interval (start, end] holds the time; a time at a stage's end
// (to round-off) belongs to that stage, the initial row to stage 0.
TEST(PostprocessorRegistry, StageColumnFollowsTheTime)
{
  const io::postprocess::StageColumn<2> column({2., 3., 13.});
  EXPECT_EQ(column.stage_of(0.), 0u);
  EXPECT_EQ(column.stage_of(2.), 0u);
  EXPECT_EQ(column.stage_of(2. - 1e-14), 0u);
  EXPECT_EQ(column.stage_of(2. + 1e-14), 0u); // round-off of a step ending on the stage's end
  EXPECT_EQ(column.stage_of(2.1), 1u);
  EXPECT_EQ(column.stage_of(3.), 1u);
  EXPECT_EQ(column.stage_of(13.), 2u);
}
