#include <ausroll/io/owned_cell_around_point.h>

#include <deal.II/grid/grid_tools.h>

namespace ausroll::io
{
  using namespace dealii;

  template <int dim>
  std::optional<std::pair<typename DoFHandler<dim>::active_cell_iterator, Point<dim>>>
  owned_cell_around_point(const Mapping<dim>    &mapping,
                          const DoFHandler<dim> &dof_handler,
                          const Point<dim>      &p,
                          const double           tolerance)
  {
    try
    {
      for (const auto &[cell, unit] :
           GridTools::find_all_active_cells_around_point(mapping, dof_handler, p, tolerance))
        if (cell.state() == IteratorState::valid && cell->is_locally_owned())
          return std::make_pair(cell, GeometryInfo<dim>::project_to_unit_cell(unit));
    }
    catch (...)
    {
      // not in the part of the mesh this rank knows (deal.II throws ExcPointNotFound)
    }
    return std::nullopt;
  }

  template std::optional<std::pair<DoFHandler<2>::active_cell_iterator, Point<2>>>
  owned_cell_around_point(const Mapping<2> &, const DoFHandler<2> &, const Point<2> &, double);
  template std::optional<std::pair<DoFHandler<3>::active_cell_iterator, Point<3>>>
  owned_cell_around_point(const Mapping<3> &, const DoFHandler<3> &, const Point<3> &, double);
} // namespace ausroll::io
