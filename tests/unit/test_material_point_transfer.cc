// Unit tests of the material-point transfer across refinement and coarsening.
#include <ausroll/adaptivity/material_point_transfer.h>
#include <ausroll/material/plasticity_model.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>

#include <gtest/gtest.h>

using namespace dealii;
using ausroll::adaptivity::MaterialPointTransfer;
using ausroll::material::MaterialPoint;

namespace
{
  /** A state that depends on the reference position: distinct values at every point. */
  void set_state(MaterialPoint &p, const Point<2> &x)
  {
    p.committed.stress[0][0] = 100. * x[0];
    p.committed.stress[1][1] = -50. * x[1];
    p.committed.stress[0][1] = 10. * x[0] * x[1];
    p.committed.equivalent_plastic_strain = 0.01 * (x[0] + 2. * x[1]);
  }
} // namespace

TEST(MaterialPointTransfer, RefinementCopiesNearestParentPointAndCoarseningAverages)
{
  parallel::distributed::Triangulation<2> tria(MPI_COMM_WORLD);
  GridGenerator::hyper_cube(tria, 0., 1.);
  tria.refine_global(1);
  const QGauss<2>                             quadrature(3);
  ausroll::mechanics::MaterialPointStorage<2> storage;
  storage.initialize(tria.begin_active(), tria.end(), quadrature.size());
  const MappingQ1<2> mapping;
  for (const auto &cell : tria.active_cell_iterators())
    if (cell->is_locally_owned())
    {
      const auto points = storage.get_data(cell);
      for (unsigned int q = 0; q < quadrature.size(); ++q)
        set_state(*points[q], mapping.transform_unit_to_real_cell(cell, quadrature.point(q)));
    }
  // remember the parent values (cell 0 of level 1 is refined next)
  std::vector<double> parent_xx;
  for (const auto &p : storage.get_data(tria.begin_active()))
    parent_xx.push_back(p->committed.stress[0][0]);

  MaterialPointTransfer<2> transfer(
      tria, storage, quadrature, ausroll::adaptivity::TransferMethod::nearest_point, {});
  tria.begin_active()->set_refine_flag();
  tria.prepare_coarsening_and_refinement();
  transfer.prepare();
  tria.execute_coarsening_and_refinement();
  transfer.unpack();

  // every child point carries a value of one of the parent's points, namely the nearest one
  const auto parent = tria.begin(1);
  ASSERT_TRUE(parent->has_children());
  for (unsigned int c = 0; c < 4; ++c)
  {
    const auto points = storage.get_data(parent->child(c));
    for (unsigned int q = 0; q < quadrature.size(); ++q)
    {
      const Point<2> x = mapping.transform_unit_to_real_cell(parent->child(c), quadrature.point(q));
      // nearest parent point
      double best = 1e9, expected = 0.;
      for (unsigned int p = 0; p < quadrature.size(); ++p)
      {
        const Point<2> y = mapping.transform_unit_to_real_cell(parent, quadrature.point(p));
        if (x.distance(y) < best)
        {
          best = x.distance(y);
          expected = parent_xx[p];
        }
      }
      EXPECT_DOUBLE_EQ(points[q]->committed.stress[0][0], expected);
    }
  }

  // Coarsen the children back: each parent point is the average over the child it lies in.
  std::vector<std::vector<double>> child_eps(4);
  for (unsigned int c = 0; c < 4; ++c)
    for (const auto &p : storage.get_data(parent->child(c)))
      child_eps[c].push_back(p->committed.equivalent_plastic_strain);
  for (unsigned int c = 0; c < 4; ++c)
    parent->child(c)->set_coarsen_flag();
  tria.prepare_coarsening_and_refinement();
  transfer.prepare();
  tria.execute_coarsening_and_refinement();
  transfer.unpack();
  const auto coarse = tria.begin_active();
  ASSERT_EQ(coarse->level(), 1);
  const auto points = storage.get_data(coarse);
  for (unsigned int q = 0; q < quadrature.size(); ++q)
  {
    const unsigned int c = GeometryInfo<2>::child_cell_from_point(quadrature.point(q));
    double             average = 0.;
    for (const double e : child_eps[c])
      average += e / child_eps[c].size();
    EXPECT_NEAR(points[q]->committed.equivalent_plastic_strain, average, 1e-15);
  }
}

TEST(MaterialPointTransfer, PolynomialTransferIsExactForQuadraticFields)
{
  // The state of set_state() is (bi)quadratic in x: interpolation through the 3x3 Gauss points
  // (refinement) and the least-squares fit (coarsening) must reproduce it to round-off.
  parallel::distributed::Triangulation<2> tria(MPI_COMM_WORLD);
  GridGenerator::hyper_cube(tria, 0., 1.);
  tria.refine_global(1);
  const QGauss<2>                             quadrature(3);
  ausroll::mechanics::MaterialPointStorage<2> storage;
  storage.initialize(tria.begin_active(), tria.end(), quadrature.size());
  const MappingQ1<2> mapping;
  auto               fill = [&]()
  {
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned())
      {
        const auto points = storage.get_data(cell);
        for (unsigned int q = 0; q < quadrature.size(); ++q)
          set_state(*points[q], mapping.transform_unit_to_real_cell(cell, quadrature.point(q)));
      }
  };
  auto max_error = [&]()
  {
    double error = 0.;
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned())
      {
        const auto points = storage.get_data(cell);
        for (unsigned int q = 0; q < quadrature.size(); ++q)
        {
          MaterialPoint expected;
          set_state(expected, mapping.transform_unit_to_real_cell(cell, quadrature.point(q)));
          error = std::max(error, (points[q]->committed.stress - expected.committed.stress).norm());
          error = std::max(error,
                           std::abs(points[q]->committed.equivalent_plastic_strain
                                    - expected.committed.equivalent_plastic_strain));
        }
      }
    return error;
  };
  fill();
  MaterialPointTransfer<2> transfer(
      tria, storage, quadrature, ausroll::adaptivity::TransferMethod::polynomial, {});
  tria.begin_active()->set_refine_flag();
  tria.prepare_coarsening_and_refinement();
  transfer.prepare();
  tria.execute_coarsening_and_refinement();
  transfer.unpack();
  EXPECT_LT(max_error(), 1e-11);

  fill();
  for (unsigned int c = 0; c < 4; ++c)
    tria.begin(1)->child(c)->set_coarsen_flag();
  tria.prepare_coarsening_and_refinement();
  transfer.prepare();
  tria.execute_coarsening_and_refinement();
  transfer.unpack();
  EXPECT_LT(max_error(), 1e-11);
}

TEST(MaterialPointTransfer, ProjectionOntoYieldSurface)
{
  ausroll::material::MaterialParameters       mp;
  const ausroll::material::VonMisesPlasticity vm(mp);
  SymmetricTensor<2, 3>                       s;
  s[0][0] = 300.;
  s[1][1] = 20.;
  const SymmetricTensor<2, 3> p = vm.project_onto_yield_surface(s, SymmetricTensor<2, 3>(), 0., 0.);
  EXPECT_NEAR(vm.yield_function(p, SymmetricTensor<2, 3>(), 0., 0.), 0., 1e-10);
  EXPECT_NEAR(trace(p), trace(s), 1e-12);
  SymmetricTensor<2, 3> inside;
  inside[0][0] = 100.;
  EXPECT_EQ(vm.project_onto_yield_surface(inside, SymmetricTensor<2, 3>(), 0., 0.), inside);
}

TEST(MaterialPointTransfer, AveragingKeepsStatesAdmissible)
{
  // Convexity: the average of states on (or inside) the yield surface with their own hardening is
  // admissible -- the reason coarsening averages instead of interpolating.
  ausroll::material::MaterialParameters mp;
  mp.hardening_modulus = 1000.;
  const ausroll::material::VonMisesPlasticity vm(mp);
  SymmetricTensor<2, 3>                       s1, s2;
  s1[0][0] = 240. + 1000. * 0.01;  // uniaxial, on the surface for alpha = 0.01
  s2[0][1] = 240. / std::sqrt(3.); // pure shear, on the surface for alpha = 0
  EXPECT_NEAR(vm.yield_function(s1, SymmetricTensor<2, 3>(), 0.01, 0.), 0., 1e-10);
  EXPECT_NEAR(vm.yield_function(s2, SymmetricTensor<2, 3>(), 0., 0.), 0., 1e-10);
  EXPECT_LE(vm.yield_function(0.5 * (s1 + s2), SymmetricTensor<2, 3>(), 0.005, 0.), 1e-10);
}
