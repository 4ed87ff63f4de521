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
#include <functional>
#include <map>

using namespace dealii;

namespace
{
  // A flat die along the top face y = L of the square [0, L]^2 (the cube [0, L]^3): distance L - y.
  constexpr double L = 16.;

  template <int dim>
  double distance_to_top(const Point<dim> &x)
  {
    return L - x[1];
  }

  /** One marking cycle of mark_cells() on a Q1 vector field, with the material points (4 per
      cell) set from @p plastic_strain at each cell centre (a stand-in for the material-point
      transfer, which is tested in test_material_point_transfer.cc), and the die at
      @p die_distance. Returns what mark_cells() returns: whether any cell was flagged. */
  template <int dim>
  bool mark_once(const ausroll::adaptivity::AdaptivityParameters &parameters,
                 parallel::distributed::Triangulation<dim>       &tria,
                 const std::function<double(const Point<dim> &)> &plastic_strain,
                 const ausroll::adaptivity::DieDistance<dim>     &die_distance)
  {
    const FESystem<dim>  fe(FE_Q<dim>(1), dim);
    const MappingQ1<dim> mapping;
    DoFHandler<dim>      dof_handler(tria);
    dof_handler.distribute_dofs(fe);
    TrilinosWrappers::MPI::Vector solution(dof_handler.locally_owned_dofs(), MPI_COMM_WORLD);
    ausroll::mechanics::MaterialPointStorage<dim> points;
    points.initialize(tria.begin_active(), tria.end(), 4);
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto &point : points.get_data(cell))
        point->committed.equivalent_plastic_strain = plastic_strain(cell->center());
    return ausroll::adaptivity::mark_cells<dim>(
        parameters, tria, mapping, dof_handler, solution, points, die_distance);
  }

  /** Mark and execute up to 8 cycles (enough for 4 levels and the coarsening; mark_cells() also
      reports coarsen flags that deal.II drops because a sibling is not flagged, so its return
      value does not tell when the mesh has settled). */
  template <int dim>
  void adapt_cycles(const ausroll::adaptivity::AdaptivityParameters &parameters,
                    parallel::distributed::Triangulation<dim>       &tria,
                    const std::function<double(const Point<dim> &)> &plastic_strain,
                    const ausroll::adaptivity::DieDistance<dim>     &die_distance)
  {
    for (unsigned int cycle = 0; cycle < 8; ++cycle)
    {
      if (!mark_once<dim>(parameters, tria, plastic_strain, die_distance))
        return;
      tria.execute_coarsening_and_refinement();
    }
  }

  /** The contact indicator with the die on the top face and no plastic strain. */
  void adapt(const ausroll::adaptivity::AdaptivityParameters &parameters,
             parallel::distributed::Triangulation<2>         &tria)
  {
    adapt_cycles<2>(
        parameters, tria, [](const Point<2> &) { return 0.; }, distance_to_top<2>);
  }

  ausroll::adaptivity::AdaptivityParameters contact_parameters(const double fine_band)
  {
    ausroll::adaptivity::AdaptivityParameters p;
    p.indicators = {"contact"};
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
  {
    if (distance_to_top<2>(cell->center()) < 6.)
    {
      EXPECT_EQ(cell->level(), 4) << "cell at " << cell->center();
    }
  }
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
      const double d = distance_to_top<2>(cell->center());
      if (d < fine)
      {
        EXPECT_EQ(cell->level(), 4) << "cell at " << cell->center();
      }
      else if (d < 6.)
      {
        EXPECT_GE(cell->level(), 3) << "cell at " << cell->center();
      }
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
  template <int dim>
  double plastic_strain_at(const Point<dim> &x)
  {
    return x[1] < 0.5 * L ? 0.1 : 0.;
  }

  ausroll::adaptivity::AdaptivityParameters plastic_parameters(const int plastic_level)
  {
    ausroll::adaptivity::AdaptivityParameters p;
    p.indicators = {"contact"};
    p.contact_band = 1.;
    p.max_level = 2;
    p.keep_plastic_strain = 0.05;
    p.plastic_coarsening_level = plastic_level;
    return p;
  }
} // namespace

namespace
{
  // Behind the die (farther than the coarsening distance), a 4 x 4 (x 4) coarse mesh refined
  // uniformly to level 2 coarsens: the plastic lower half (0.1 > Keep plastic strain above = 0.05)
  // stays at level 2 with Plastic coarsening level = -1 (off, the rule before) and is coarsened to
  // that level, not further, with 0, 1 or 2; the elastic upper half goes back to level 0 (Minimum
  // level) except the coarse row next to the plastic one, which the 2:1 balance of the distributed
  // mesh keeps at most one level below its neighbours. The same in 2D and 3D: the rule reads only
  // the cell's level and its material points.
  template <int dim>
  void check_plastic_coarsening_floor()
  {
    for (const int plastic_level : {-1, 0, 1, 2})
    {
      parallel::distributed::Triangulation<dim> tria(MPI_COMM_WORLD);
      GridGenerator::subdivided_hyper_cube(tria, 4, 0., L);
      tria.refine_global(2);
      adapt_cycles<dim>(plastic_parameters(plastic_level),
                        tria,
                        plastic_strain_at<dim>,
                        [](const Point<dim> &) { return 100.; });
      const int    expected_plastic = plastic_level < 0 ? 2 : plastic_level;
      unsigned int n_plastic = 0;
      for (const auto &cell : tria.active_cell_iterators())
        if (plastic_strain_at<dim>(cell->center()) > 0.05)
        {
          ++n_plastic;
          EXPECT_EQ(cell->level(), expected_plastic)
              << dim << "D plastic cell at " << cell->center() << ", Plastic coarsening level "
              << plastic_level;
        }
        else if (cell->center()[1] > 12.)
        {
          EXPECT_EQ(cell->level(), 0) << dim << "D elastic cell at " << cell->center()
                                      << ", Plastic coarsening level " << plastic_level;
        }
        else
        {
          EXPECT_EQ(cell->level(), std::max(expected_plastic - 1, 0))
              << dim << "D elastic cell at " << cell->center() << ", Plastic coarsening level "
              << plastic_level;
        }
      // the lower half of the 4^dim coarse cells, each split into 2^(dim level) cells
      EXPECT_EQ(n_plastic, (1u << (dim * expected_plastic)) * (dim == 2 ? 8u : 32u));
    }
  }

  // Near the die (closer than the coarsening distance) the plastic cells keep the finest level
  // whatever Plastic coarsening level says: the rule acts only once the die has left.
  template <int dim>
  void check_no_plastic_coarsening_at_the_die()
  {
    auto parameters = plastic_parameters(1);
    parameters.keep_plastic_strain = 1e-3;
    // 4 mm cells (diameter 4 sqrt(dim) mm), every cell plastic, die on the top face: the default
    // coarsening distance 2 (1 + diameter) keeps every row but the lowest (centres 2, 6, 10, 14 mm
    // below the die) at level 2 in 2D (13.3 mm), every row in 3D (15.9 mm)
    const double diameter = 4. * std::sqrt(static_cast<double>(dim));
    for (const double coarsening_distance : {0., 3.})
    {
      parallel::distributed::Triangulation<dim> mesh(MPI_COMM_WORLD);
      GridGenerator::hyper_cube(mesh, 0., L);
      mesh.refine_global(2);
      parameters.coarsening_distance = coarsening_distance;
      mark_once<dim>(
          parameters, mesh, [](const Point<dim> &) { return 0.1; }, distance_to_top<dim>);
      // Coarsening distance 3 mm: cells farther than 3 + diameter (centres at 10 and 14 mm)
      const double limit
          = coarsening_distance > 0. ? coarsening_distance + diameter : 2. * (1. + diameter);
      unsigned int n_flagged = 0;
      for (const auto &cell : mesh.active_cell_iterators())
      {
        const double d = distance_to_top<dim>(cell->center());
        EXPECT_EQ(cell->coarsen_flag_set(), d > limit) << dim << "D cell at " << cell->center();
        EXPECT_FALSE(cell->refine_flag_set());
        n_flagged += cell->coarsen_flag_set() ? 1 : 0;
      }
      // cells per row of the 4^dim mesh: 4 (2D), 16 (3D); rows flagged: 2 with 3 mm, else 1 (2D)
      // or 0 (3D)
      const unsigned int per_row = dim == 2 ? 4u : 16u;
      EXPECT_EQ(n_flagged, per_row * (coarsening_distance > 0. ? 2u : (dim == 2 ? 1u : 0u)));
    }
  }
} // namespace

TEST(ContactIndicator, PlasticCoarseningLevelIsTheFloorOfPlasticCellsBehindTheDie)
{
  check_plastic_coarsening_floor<2>();
}

TEST(ContactIndicator, PlasticCoarseningLevelIsTheFloorOfPlasticCellsBehindTheDie3d)
{
  check_plastic_coarsening_floor<3>();
}

TEST(ContactIndicator, PlasticCoarseningLevelDoesNotCoarsenAtTheDie)
{
  check_no_plastic_coarsening_at_the_die<2>();
}

TEST(ContactIndicator, PlasticCoarseningLevelDoesNotCoarsenAtTheDie3d)
{
  check_no_plastic_coarsening_at_the_die<3>();
}

// `Adaptivity/Indicators` lists the registered indicators; a selection is read into the names in
// the registry's order, each once, whatever order and repetitions the entry has.
TEST(IndicatorRegistry, RegisteredIndicatorsAndSelection)
{
  using ausroll::adaptivity::AdaptivityParameters;
  EXPECT_EQ(ausroll::adaptivity::IndicatorRegistry::instance().names(),
            (std::vector<std::string>{"Kelly", "contact", "plastic strain"}));
  dealii::ParameterHandler prm;
  AdaptivityParameters::declare_parameters(prm);
  prm.parse_input_from_string(
      "subsection Adaptivity\nset Indicators = plastic strain, Kelly, plastic strain\nend\n");
  AdaptivityParameters p;
  p.parse_parameters(prm);
  EXPECT_EQ(p.indicators, (std::vector<std::string>{"Kelly", "plastic strain"}));
}
