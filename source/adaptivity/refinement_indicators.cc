#include <ausroll/adaptivity/refinement_indicators.h>

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/grid_refinement.h>

#include <algorithm>
#include <limits>
#include <vector>

namespace ausroll::adaptivity
{
  using namespace dealii;

  template <int dim>
  void fixed_fraction_flags(const IndicatorInput<dim> &input,
                            const Vector<float>       &indicator,
                            CellFlags                 &flags)
  {
    parallel::distributed::Triangulation<dim> &triangulation = input.triangulation;
    triangulation.clear_user_flags();
    for (const auto &cell : triangulation.active_cell_iterators())
    {
      cell->clear_refine_flag();
      cell->clear_coarsen_flag();
    }
    parallel::distributed::GridRefinement::refine_and_coarsen_fixed_fraction(
        triangulation,
        indicator,
        input.parameters.refine_fraction,
        input.parameters.coarsen_fraction);
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
      {
        const unsigned int k = cell->active_cell_index();
        flags.refine[k] = flags.refine[k] || cell->refine_flag_set();
        flags.coarsen[k] = flags.coarsen[k] && cell->coarsen_flag_set();
      }
  }

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
    // Highest level a cell may be refined to, and the level above which it may be coarsened
    // even inside the contact band (Fine contact band: graded band).
    CellFlags                  flags{std::vector<bool>(n_cells, false),
                    std::vector<bool>(n_cells, true),
                    std::vector<unsigned int>(n_cells, parameters.max_level),
                    std::vector<bool>(n_cells, false)};
    std::vector<bool>         &refine = flags.refine, &coarsen = flags.coarsen;
    std::vector<unsigned int> &level_cap = flags.level_cap;
    std::vector<bool>         &coarsen_to_cap = flags.coarsen_to_cap;
    // Lowest level a cell may be coarsened to: Minimum level, or for cells kept by Keep plastic
    // strain above, Plastic coarsening level (never coarsened if that is off).
    constexpr int    never = std::numeric_limits<int>::max();
    std::vector<int> coarsen_floor(n_cells, static_cast<int>(parameters.min_level));

    const IndicatorInput<dim> input{
        parameters, triangulation, mapping, dof_handler, solution, material_points, die_distance};
    const auto &indicators = IndicatorRegistry::instance();
    for (const std::string &name : parameters.indicators)
      indicators.get(name, "Adaptivity/Indicators").make()->mark(input, flags);

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

    if (parameters.case_level >= 0)
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto &point : material_points.get_data(cell))
            if (point->committed.carbon > parameters.case_carbon)
            {
              const unsigned int k = cell->active_cell_index();
              if (cell->level() < parameters.case_level)
                refine[k] = true;
              coarsen_floor[k] = std::max(coarsen_floor[k], parameters.case_level);
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

  template void
  fixed_fraction_flags<2>(const IndicatorInput<2> &, const Vector<float> &, CellFlags &);
  template void
  fixed_fraction_flags<3>(const IndicatorInput<3> &, const Vector<float> &, CellFlags &);
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
