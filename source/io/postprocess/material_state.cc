#include <ausroll/io/postprocess/material_state.h>

#include <deal.II/base/mpi.h>

namespace ausroll::io::postprocess
{
  using namespace dealii;

  template <int dim>
  YieldExcess<dim>::YieldExcess(const double yield_stress)
      : yield_stress(yield_stress)
  {
  }

  template <int dim>
  void YieldExcess<dim>::execute(const PostprocessInput<dim> &input, HistoryRow &row) const
  {
    double excess = -1.;
    for (const auto &cell : input.dof_handler.get_triangulation().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto &point : input.material_points.get_data(cell))
          excess = std::max(excess, input.model.yield_function(point->committed));
    const MPI_Comm comm = input.dof_handler.get_communicator();
    row.emplace_back("yield_excess",
                     std::max(0., Utilities::MPI::max(excess, comm)) / yield_stress);
  }

  template <int dim>
  void CellAverages<dim>::cell_fields(const PostprocessInput<dim> &input,
                                      std::vector<CellField>      &fields) const
  {
    const Triangulation<dim> &triangulation = input.dof_handler.get_triangulation();
    const unsigned int        n = triangulation.n_active_cells();
    const std::size_t         first = fields.size();
    for (const char *name : {"stress_xx",
                             "stress_yy",
                             "stress_zz",
                             "stress_xy",
                             "von_mises_stress",
                             "equivalent_plastic_strain",
                             "subdomain",
                             "level"})
      fields.emplace_back(name, Vector<float>(n));
    CellField *f = &fields[first];

    for (const auto &cell : triangulation.active_cell_iterators())
    {
      const unsigned int k = cell->active_cell_index();
      f[6].second[k] = cell->subdomain_id();
      f[7].second[k] = cell->level();
      if (!cell->is_locally_owned())
        continue;
      const auto points = input.material_points.get_data(cell);
      double     s[6] = {0, 0, 0, 0, 0, 0};
      for (const auto &p : points)
      {
        const auto &st = p->committed;
        s[0] += st.stress[0][0];
        s[1] += st.stress[1][1];
        s[2] += st.stress[2][2];
        s[3] += st.stress[0][1];
        s[4] += st.von_mises_stress();
        s[5] += st.equivalent_plastic_strain;
      }
      for (unsigned int i = 0; i < 6; ++i)
        f[i].second[k] = s[i] / points.size();
    }
  }

  template class YieldExcess<2>;
  template class CellAverages<2>;
  template class YieldExcess<3>;
  template class CellAverages<3>;
} // namespace ausroll::io::postprocess
