// Unit tests of the contact indicator of mesh adaptation (Adaptivity/Contact band and the graded
// band of Adaptivity/Fine contact band).
#include <ausroll/adaptivity/refinement_indicators.h>

#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/trilinos_vector.h>

#include <gtest/gtest.h>

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
