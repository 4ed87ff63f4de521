#include <ausroll/adaptivity/refinement_indicators.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/grid_refinement.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/numerics/error_estimator.h>

#include <algorithm>
#include <limits>
#include <vector>

namespace ausroll::adaptivity
{
  using namespace dealii;

  namespace
  {
    /** Run a fixed-fraction marking on @p indicator and return the flags it would set. */
    template <int dim>
    void fixed_fraction_flags(parallel::distributed::Triangulation<dim> &triangulation,
                              const Vector<float>                       &indicator,
                              const double                               refine_fraction,
                              const double                               coarsen_fraction,
                              std::vector<bool>                         &refine,
                              std::vector<bool>                         &coarsen)
    {
      triangulation.clear_user_flags();
      for (const auto &cell : triangulation.active_cell_iterators())
      {
        cell->clear_refine_flag();
        cell->clear_coarsen_flag();
      }
      parallel::distributed::GridRefinement::refine_and_coarsen_fixed_fraction(
          triangulation, indicator, refine_fraction, coarsen_fraction);
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned())
        {
          const unsigned int k = cell->active_cell_index();
          refine[k] = refine[k] || cell->refine_flag_set();
          coarsen[k] = coarsen[k] && cell->coarsen_flag_set();
        }
    }
  } // namespace

  template <int dim>
  bool mark_cells(const AdaptivityParameters                 &parameters,
                  parallel::distributed::Triangulation<dim>  &triangulation,
                  const Mapping<dim>                         &mapping,
                  const DoFHandler<dim>                      &dof_handler,
                  const TrilinosWrappers::MPI::Vector        &solution,
                  const mechanics::MaterialPointStorage<dim> &material_points,
                  const DieDistance<dim>                     &die_distance)
  {
    const unsigned int n_cells = triangulation.n_active_cells();
    std::vector<bool>  refine(n_cells, false), coarsen(n_cells, true);
    // Highest level a cell may be refined to, and the level above which it may be coarsened
    // even inside the contact band (Fine contact band: graded band).
    std::vector<unsigned int> level_cap(n_cells, parameters.max_level);
    std::vector<bool>         coarsen_to_cap(n_cells, false);
    // Lowest level a cell may be coarsened to: Minimum level, or for cells kept by Keep plastic
    // strain above, Plastic coarsening level (never coarsened if that is off).
    constexpr int    never = std::numeric_limits<int>::max();
    std::vector<int> coarsen_floor(n_cells, static_cast<int>(parameters.min_level));

    if (parameters.kelly)
    {
      Vector<float> indicator(n_cells);
      KellyErrorEstimator<dim>::estimate(mapping,
                                         dof_handler,
                                         QGauss<dim - 1>(dof_handler.get_fe().degree + 1),
                                         {},
                                         solution,
                                         indicator,
                                         ComponentMask(),
                                         nullptr,
                                         numbers::invalid_unsigned_int,
                                         triangulation.locally_owned_subdomain());
      fixed_fraction_flags(triangulation,
                           indicator,
                           parameters.refine_fraction,
                           parameters.coarsen_fraction,
                           refine,
                           coarsen);
    }

    if (parameters.plastic_strain)
    {
      Vector<float> indicator(n_cells);
      double        largest = 0.;
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned())
        {
          double lo = std::numeric_limits<double>::max(), hi = 0.;
          for (const auto &point : material_points.get_data(cell))
          {
            lo = std::min(lo, point->committed.equivalent_plastic_strain);
            hi = std::max(hi, point->committed.equivalent_plastic_strain);
          }
          indicator[cell->active_cell_index()] = hi - lo;
          largest = std::max(largest, hi - lo);
        }
      if (Utilities::MPI::max(largest, triangulation.get_communicator()) > 0.)
        fixed_fraction_flags(triangulation,
                             indicator,
                             parameters.refine_fraction,
                             parameters.coarsen_fraction,
                             refine,
                             coarsen);
    }

    if (parameters.contact && die_distance)
    {
      // Deformed cell centre from the displacement at the reference centre.
      Point<dim> unit_centre;
      for (unsigned int d = 0; d < dim; ++d)
        unit_centre[d] = 0.5;
      const Quadrature<dim> centre(unit_centre);
      FEValues<dim>         fe_values(
          mapping, dof_handler.get_fe(), centre, update_values | update_quadrature_points);
      std::vector<Tensor<1, dim>>      u(1);
      const FEValuesExtractors::Vector displacement(0);
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[displacement].get_function_values(solution, u);
          const Point<dim> x = fe_values.quadrature_point(0) + u[0];
          const double     d = die_distance(x);
          const double     size = cell->diameter();
          const unsigned   k = cell->active_cell_index();
          if (d < parameters.contact_band + 0.5 * size)
            refine[k] = true;
          const double coarsening_distance = parameters.coarsening_distance > 0.
                                                 ? parameters.coarsening_distance + size
                                                 : 2. * (parameters.contact_band + size);
          if (d < coarsening_distance)
            coarsen[k] = false;
          if (parameters.fine_contact_band > 0.)
          {
            if (!(d < parameters.fine_contact_band + 0.5 * size))
              level_cap[k] = parameters.max_level - 1;
            if (!(d < 2. * (parameters.fine_contact_band + size)))
              coarsen_to_cap[k] = true;
          }
        }
    }

    if (parameters.keep_plastic_strain > 0.)
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto &point : material_points.get_data(cell))
            if (point->committed.equivalent_plastic_strain > parameters.keep_plastic_strain)
            {
              const unsigned int k = cell->active_cell_index();
              coarsen_floor[k]
                  = parameters.plastic_coarsening_level < 0
                        ? never
                        : std::max(coarsen_floor[k], parameters.plastic_coarsening_level);
              break;
            }

    // Apply the flags with the limits.
    bool any = false;
    for (const auto &cell : triangulation.active_cell_iterators())
    {
      cell->clear_refine_flag();
      cell->clear_coarsen_flag();
      if (!cell->is_locally_owned())
        continue;
      const unsigned int k = cell->active_cell_index();
      const int          level = cell->level();
      if (refine[k] && level < static_cast<int>(level_cap[k])
          && 0.5 * cell->minimum_vertex_distance() >= parameters.min_cell_size)
      {
        cell->set_refine_flag();
        any = true;
      }
      else if (level > coarsen_floor[k]
               && ((coarsen[k] && !refine[k])
                   || (coarsen_to_cap[k] && level > static_cast<int>(level_cap[k]))))
      {
        cell->set_coarsen_flag();
        any = true;
      }
    }
    return Utilities::MPI::logical_or(any, triangulation.get_communicator());
  }

  template bool mark_cells<2>(const AdaptivityParameters &,
                              parallel::distributed::Triangulation<2> &,
                              const Mapping<2> &,
                              const DoFHandler<2> &,
                              const TrilinosWrappers::MPI::Vector &,
                              const mechanics::MaterialPointStorage<2> &,
                              const DieDistance<2> &);
  template bool mark_cells<3>(const AdaptivityParameters &,
                              parallel::distributed::Triangulation<3> &,
                              const Mapping<3> &,
                              const DoFHandler<3> &,
                              const TrilinosWrappers::MPI::Vector &,
                              const mechanics::MaterialPointStorage<3> &,
                              const DieDistance<3> &);
} // namespace ausroll::adaptivity
