// Unit tests of the contact indicator of mesh adaptation (Adaptivity/Contact band, the graded
// band of Adaptivity/Fine contact band, Adaptivity/Coarsening distance) and of the coarsening of
// plastic cells (Keep plastic strain above, Plastic coarsening level).
#include <ausroll/adaptivity/refinement_indicators.h>

#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/trilinos_vector.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

using namespace dealii;

namespace
{
  // A flat die along the top face y = L of the square [0, L]^2: distance L - y.
  constexpr double L = 16.;

  double distance_to_top(const Point<2> &x)
  {
    return L - x[1];
  }

  /** Mark and execute 8 cycles (enough for 4 levels and the coarsening; mark_cells() also
      reports coarsen flags that deal.II drops because a sibling is not flagged, so its return
      value does not tell when the mesh has settled). */
  void adapt(const ausroll::adaptivity::AdaptivityParameters &parameters,
             parallel::distributed::Triangulation<2>         &tria)
  {
    const FESystem<2>                           fe(FE_Q<2>(1), 2);
    const MappingQ1<2>                          mapping;
    ausroll::mechanics::MaterialPointStorage<2> points; // not read by the contact indicator
    for (unsigned int cycle = 0; cycle < 8; ++cycle)
    {
      DoFHandler<2> dof_handler(tria);
      dof_handler.distribute_dofs(fe);
      TrilinosWrappers::MPI::Vector solution(dof_handler.locally_owned_dofs(), MPI_COMM_WORLD);
      if (!ausroll::adaptivity::mark_cells<2>(
              parameters, tria, mapping, dof_handler, solution, points, distance_to_top))
        return;
      tria.execute_coarsening_and_refinement();
    }
  }

  ausroll::adaptivity::AdaptivityParameters contact_parameters(const double fine_band)
  {
    ausroll::adaptivity::AdaptivityParameters p;
    p.contact = true;
    p.contact_band = 6.;
    p.fine_contact_band = fine_band;
    p.max_level = 4; // cells of 16, 8, 4, 2, 1 mm
    return p;
  }

  /** Number of active cells per level. */
  std::map<int, unsigned int> cells_per_level(const parallel::distributed::Triangulation<2> &tria)
  {
    std::map<int, unsigned int> n;
    for (const auto &cell : tria.active_cell_iterators())
      ++n[cell->level()];
    return n;
  }
} // namespace

// Without a fine band every cell whose centre lies in the band reaches the maximum level.
TEST(ContactIndicator, UniformBandRefinesTheWholeBandToTheMaximumLevel)
{
  parallel::distributed::Triangulation<2> tria(MPI_COMM_WORLD);
  GridGenerator::hyper_cube(tria, 0., L);
  adapt(contact_parameters(0.), tria);
  for (const auto &cell : tria.active_cell_iterators())
    if (distance_to_top(cell->center()) < 6.)
      EXPECT_EQ(cell->level(), 4) << "cell at " << cell->center();
}

// Graded band: the finest level only within the fine band; the rest of the band one level
// coarser, never coarser than that; and a uniform band, re-marked with a fine band, coarsens its
// finest cells beyond twice the fine band (plus their size) to the level below.
TEST(ContactIndicator, FineBandGradesTheBandAndCoarsensTheFinestLevelOutsideIt)
{
  const double fine = 1.;
  for (const bool from_uniform : {false, true})
  {
    parallel::distributed::Triangulation<2> tria(MPI_COMM_WORLD);
    GridGenerator::hyper_cube(tria, 0., L);
    unsigned int n_finest_uniform = 0;
    if (from_uniform)
    {
      adapt(contact_parameters(0.), tria);
      n_finest_uniform = cells_per_level(tria).at(4);
    }
    adapt(contact_parameters(fine), tria);
    for (const auto &cell : tria.active_cell_iterators())
    {
      const double d = distance_to_top(cell->center());
      if (d < fine)
        EXPECT_EQ(cell->level(), 4) << "cell at " << cell->center();
      else if (d < 6.)
        EXPECT_GE(cell->level(), 3) << "cell at " << cell->center();
      if (cell->level() == 4)
      {
        // refined: its parent (diameter 2 sqrt 2) was closer than fine + half its diameter;
        // kept: closer than twice (fine + its diameter), or a sibling was (siblings coarsen
        // together: + 1 mm)
        const double limit = from_uniform ? 2. * (fine + cell->diameter()) + 1.
                                          : fine + 0.5 * cell->parent()->diameter() + 0.5;
        EXPECT_LT(d, limit) << "cell at " << cell->center();
      }
    }
    const unsigned int n_finest = cells_per_level(tria).at(4);
    if (from_uniform)
    {
      // the uniform band has 8 rows of 1 mm cells (centres 0.5 ... 7.5 mm below the die); the
      // two rows of the parents at 7 mm are coarsened, 6 rows stay
      EXPECT_EQ(n_finest_uniform, 8u * 16u);
      EXPECT_EQ(n_finest, 6u * 16u);
    }
    else // refined from the coarse mesh: the rows at 0.5 and 1.5 mm only
      EXPECT_EQ(n_finest, 2u * 16u);
  }
}

namespace
{
  /** Plastic strain field of the tests below: 0.1 in the lower half y < L/2, 0 above. */
  double plastic_strain_at(const Point<2> &x)
  {
    return x[1] < 0.5 * L ? 0.1 : 0.;
  }

  /** Mark and execute up to 8 cycles with the die far away (the die has left: distance 100 mm)
      and the material points set from plastic_strain_at() at each cell centre (a stand-in for the
      material-point transfer, which is tested in test_material_point_transfer.cc). */
  void adapt_behind_die(const ausroll::adaptivity::AdaptivityParameters &parameters,
                        parallel::distributed::Triangulation<2>         &tria)
  {
    const FESystem<2>  fe(FE_Q<2>(1), 2);
    const MappingQ1<2> mapping;
    for (unsigned int cycle = 0; cycle < 8; ++cycle)
    {
      DoFHandler<2> dof_handler(tria);
      dof_handler.distribute_dofs(fe);
      TrilinosWrappers::MPI::Vector solution(dof_handler.locally_owned_dofs(), MPI_COMM_WORLD);
      ausroll::mechanics::MaterialPointStorage<2> points;
      points.initialize(tria.begin_active(), tria.end(), 4);
      for (const auto &cell : tria.active_cell_iterators())
        for (const auto &point : points.get_data(cell))
          point->committed.equivalent_plastic_strain = plastic_strain_at(cell->center());
      if (!ausroll::adaptivity::mark_cells<2>(parameters,
                                              tria,
                                              mapping,
                                              dof_handler,
                                              solution,
                                              points,
                                              [](const Point<2> &) { return 100.; }))
        return;
      tria.execute_coarsening_and_refinement();
    }
  }

  ausroll::adaptivity::AdaptivityParameters plastic_parameters(const int plastic_level)
  {
    ausroll::adaptivity::AdaptivityParameters p;
    p.contact = true;
    p.contact_band = 1.;
    p.max_level = 2;
    p.keep_plastic_strain = 0.05;
    p.plastic_coarsening_level = plastic_level;
    return p;
  }
} // namespace

// Behind the die (farther than the coarsening distance), a 4 x 4 coarse mesh refined uniformly to
// level 2 coarsens: the plastic lower half (0.1 > Keep plastic strain above = 0.05) stays at level
// 2 with Plastic coarsening level = -1 (off, the rule before) and is coarsened to that level, not
// further, with 0, 1 or 2; the elastic upper half goes back to level 0 (Minimum level) except the
// coarse row next to the plastic one, which the 2:1 balance of the distributed mesh keeps at most
// one level below its neighbours.
TEST(ContactIndicator, PlasticCoarseningLevelIsTheFloorOfPlasticCellsBehindTheDie)
{
  for (const int plastic_level : {-1, 0, 1, 2})
  {
    parallel::distributed::Triangulation<2> tria(MPI_COMM_WORLD);
    GridGenerator::subdivided_hyper_cube(tria, 4, 0., L);
    tria.refine_global(2);
    adapt_behind_die(plastic_parameters(plastic_level), tria);
    const int expected_plastic = plastic_level < 0 ? 2 : plastic_level;
    for (const auto &cell : tria.active_cell_iterators())
      if (plastic_strain_at(cell->center()) > 0.05)
        EXPECT_EQ(cell->level(), expected_plastic)
            << "plastic cell at " << cell->center() << ", Plastic coarsening level "
            << plastic_level;
      else if (cell->center()[1] > 12.)
        EXPECT_EQ(cell->level(), 0) << "elastic cell at " << cell->center()
                                    << ", Plastic coarsening level " << plastic_level;
      else
        EXPECT_EQ(cell->level(), std::max(expected_plastic - 1, 0))
            << "elastic cell at " << cell->center() << ", Plastic coarsening level "
            << plastic_level;
  }
}

// Near the die (closer than the coarsening distance) the plastic cells keep the finest level
// whatever Plastic coarsening level says: the rule acts only once the die has left.
TEST(ContactIndicator, PlasticCoarseningLevelDoesNotCoarsenAtTheDie)
{
  auto parameters = plastic_parameters(1);
  parameters.keep_plastic_strain = 1e-3;
  // 4 mm cells (diameter 5.66 mm), every cell plastic, die on the top face: the default coarsening
  // distance 2 (1 + 5.66) = 13.3 mm keeps every row but the lowest (centres 2, 6, 10, 14 mm below
  // the die) at level 2
  const FESystem<2>  fe(FE_Q<2>(1), 2);
  const MappingQ1<2> mapping;
  for (const double coarsening_distance : {0., 3.})
  {
    parallel::distributed::Triangulation<2> mesh(MPI_COMM_WORLD);
    GridGenerator::hyper_cube(mesh, 0., L);
    mesh.refine_global(2);
    parameters.coarsening_distance = coarsening_distance;
    DoFHandler<2> dof_handler(mesh);
    dof_handler.distribute_dofs(fe);
    TrilinosWrappers::MPI::Vector solution(dof_handler.locally_owned_dofs(), MPI_COMM_WORLD);
    ausroll::mechanics::MaterialPointStorage<2> points;
    points.initialize(mesh.begin_active(), mesh.end(), 4);
    for (const auto &cell : mesh.active_cell_iterators())
      for (const auto &point : points.get_data(cell))
        point->committed.equivalent_plastic_strain = 0.1;
    ausroll::adaptivity::mark_cells<2>(
        parameters, mesh, mapping, dof_handler, solution, points, distance_to_top);
    // Coarsening distance 3 mm: cells farther than 3 + 5.66 = 8.66 mm (centres at 10 and 14 mm)
    const double limit = coarsening_distance > 0. ? coarsening_distance + std::sqrt(32.)
                                                  : 2. * (1. + std::sqrt(32.));
    unsigned int n_flagged = 0;
    for (const auto &cell : mesh.active_cell_iterators())
    {
      const double d = distance_to_top(cell->center());
      EXPECT_EQ(cell->coarsen_flag_set(), d > limit) << "cell at " << cell->center();
      EXPECT_FALSE(cell->refine_flag_set());
      n_flagged += cell->coarsen_flag_set() ? 1 : 0;
    }
    EXPECT_EQ(n_flagged, coarsening_distance > 0. ? 8u : 4u);
  }
}
