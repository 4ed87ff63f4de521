/**
 * @file test_owned_cell_around_point.cc
 * io::owned_cell_around_point() on a distributed mesh: every point of the workpiece, also one on a
 * face, edge or vertex between cells of different ranks, is found by at least one rank in a cell
 * that rank owns and that contains it; a point outside is found by none. On one rank (the plain
 * unit run) this is the serial lookup; the ctest `unit/OwnedCellAroundPoint.mpirun=2` runs the
 * same tests on two ranks, where p4est's partition boundary runs between the cells whose
 * vertices and face centres are the test points. (A monitor point of the 3D adaptive disk scene on
 * two ranks was lost this way: deal.II's single-cell search returned on each rank a cell the other
 * rank owns.)
 */
#include <ausroll/io/owned_cell_around_point.h>

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

using namespace dealii;

namespace
{
  /**
   * The shell between the radii 0.5 and 1 (deal.II's hyper_shell, spherical manifold, MappingQ 2
   * as the scenes use on their curved rims), refined globally and then once more on the half x < 0
   * so that hanging faces meet the partition boundary. The test points are the vertices and the
   * face centres (on the curved faces, the image of the reference face centre) of every locally
   * owned cell, gathered on all ranks: every point lies on a face, edge or vertex of the mesh, and
   * on several ranks many lie between cells of different ranks.
   */
  template <int dim>
  void expect_every_mesh_point_found(const unsigned int global_refinements)
  {
    const MPI_Comm                            comm = MPI_COMM_WORLD;
    parallel::distributed::Triangulation<dim> tria(comm);
    GridGenerator::hyper_shell(tria, Point<dim>(), 0.5, 1.);
    tria.refine_global(global_refinements);
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned() && cell->center()[0] < 0)
        cell->set_refine_flag();
    tria.execute_coarsening_and_refinement();

    const FESystem<dim> fe(FE_Q<dim>(2), dim);
    DoFHandler<dim>     dof_handler(tria);
    dof_handler.distribute_dofs(fe);
    const MappingQ<dim> mapping(2);

    // the vertices and face centres of a cell
    const auto cell_points = [&mapping](const auto &cell)
    {
      std::vector<Point<dim>> result;
      for (const unsigned int v : cell->vertex_indices())
        result.push_back(cell->vertex(v));
      for (const unsigned int f : cell->face_indices())
      {
        Point<dim> unit;
        for (unsigned int d = 0; d < dim; ++d)
          unit[d] = 0.5;
        unit[f / 2] = f % 2;
        result.push_back(mapping.transform_unit_to_real_cell(cell, unit));
      }
      return result;
    };
    std::vector<Point<dim>> local_points;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const Point<dim> &p : cell_points(cell))
          local_points.push_back(p);
    std::vector<Point<dim>> points;
    for (const auto &part : Utilities::MPI::all_gather(comm, local_points))
      points.insert(points.end(), part.begin(), part.end());

    // which points this rank must find: those of its own cells (more may lie on an edge or a
    // face of one of its cells, e.g. at the hanging nodes)
    std::vector<unsigned int> must_find(points.size(), 0);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const Point<dim> &q : cell_points(cell))
          for (unsigned int i = 0; i < points.size(); ++i)
            if (points[i].distance(q) < 1e-12)
              must_find[i] = 1;

    // look every point up on every rank, then count the finders with one reduction
    std::vector<unsigned int> found_here(points.size(), 0), n_found(points.size(), 0);
    double                    max_mapping_error = 0;
    unsigned int              n_missed_own = 0;
    for (unsigned int i = 0; i < points.size(); ++i)
    {
      if (const auto found = ausroll::io::owned_cell_around_point(mapping, dof_handler, points[i]))
      {
        found_here[i] = 1;
        EXPECT_TRUE(found->first->is_locally_owned());
        const Point<dim> image = mapping.transform_unit_to_real_cell(found->first, found->second);
        max_mapping_error = std::max(max_mapping_error, image.distance(points[i]));
      }
      n_missed_own += must_find[i] && !found_here[i];
    }
    // a rank finds every point of its own cells, also those on faces shared with another rank
    // (the old single-cell search could hand both ranks the other one's cell there)
    EXPECT_EQ(Utilities::MPI::sum(n_missed_own, comm), 0u);
    Utilities::MPI::sum(found_here, comm, n_found);
    const auto n_lost = std::count(n_found.begin(), n_found.end(), 0u);
    const auto n_found_by_several
        = std::count_if(n_found.begin(), n_found.end(), [](const unsigned int n) { return n > 1; });
    // every point of the mesh has an owner
    EXPECT_EQ(n_lost, 0) << "of " << points.size() << " points";
    // the reference coordinates map back onto the point: the Newton inversion of the Q2 map
    // stops at 1e-10 in reference coordinates of cells of size 1/4 ... 1/32
    EXPECT_LT(Utilities::MPI::max(max_mapping_error, comm), 1e-9);
    // on several ranks the points do cross the partition: those between ranks are found by each
    if (Utilities::MPI::n_mpi_processes(comm) > 1)
      EXPECT_GT(n_found_by_several, 0);

    // a point outside the shell (in the hole and beyond the rim): no rank owns it
    Point<dim> in_hole, beyond;
    in_hole[0] = 0.25;
    beyond[0] = -1.05;
    for (const Point<dim> &p : {in_hole, beyond})
      EXPECT_EQ(
          Utilities::MPI::sum(
              unsigned(ausroll::io::owned_cell_around_point(mapping, dof_handler, p).has_value()),
              comm),
          0u);
  }
} // namespace

TEST(OwnedCellAroundPoint, EveryPointOfARefinedRingIsFoundByAnOwner2d)
{
  expect_every_mesh_point_found<2>(2);
}

TEST(OwnedCellAroundPoint, EveryPointOfARefinedShellIsFoundByAnOwner3d)
{
  expect_every_mesh_point_found<3>(1);
}
