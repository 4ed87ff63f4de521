#include <ausroll/io/postprocess/material_state.h>
#include <ausroll/io/postprocess/standard_set.h>
#include <ausroll/material/tensor_functions.h>

#include <deal.II/base/mpi.h>

namespace ausroll::io::postprocess
{
  using namespace dealii;

  SymmetricTensor<2, 3> strain_tensor(const material::MaterialState &state, const bool small_strain)
  {
    const Tensor<2, 3> &F = state.deformation_gradient;
    if (small_strain)
      return symmetrize(F) - unit_symmetric_tensor<3>();
    return 0.5 * material::logarithm(symmetrize(F * transpose(F)));
  }

  template <int dim>
  std::vector<std::pair<std::string, std::array<unsigned int, 2>>> tensor_components()
  {
    std::vector<std::pair<std::string, std::array<unsigned int, 2>>> c{
        {"xx", {{0, 0}}}, {"yy", {{1, 1}}}, {"zz", {{2, 2}}}, {"xy", {{0, 1}}}};
    if (dim == 3)
    {
      c.push_back({"xz", {{0, 2}}});
      c.push_back({"yz", {{1, 2}}});
    }
    return c;
  }

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

    // appended after the fields above (their order is kept): the shear stresses of 3D and the
    // strain tensor
    const auto         components = tensor_components<dim>();
    const bool         small_strain = input.model.is_small_strain();
    const std::size_t  first_shear = fields.size();
    const unsigned int n_shear = dim == 3 ? 2 : 0;
    for (unsigned int i = 4; i < 4 + n_shear; ++i)
      fields.emplace_back("stress_" + components[i].first, Vector<float>(n));
    const std::size_t first_strain = fields.size();
    for (const auto &c : components)
      fields.emplace_back("strain_" + c.first, Vector<float>(n));
    for (const auto &cell : triangulation.active_cell_iterators())
    {
      if (!cell->is_locally_owned())
        continue;
      const unsigned int  k = cell->active_cell_index();
      const auto          points = input.material_points.get_data(cell);
      std::vector<double> shear(n_shear, 0.), strain(components.size(), 0.);
      for (const auto &p : points)
      {
        const SymmetricTensor<2, 3> eps = strain_tensor(p->committed, small_strain);
        for (unsigned int i = 0; i < n_shear; ++i)
          shear[i] += p->committed.stress[components[4 + i].second[0]][components[4 + i].second[1]];
        for (unsigned int i = 0; i < components.size(); ++i)
          strain[i] += eps[components[i].second[0]][components[i].second[1]];
      }
      for (unsigned int i = 0; i < n_shear; ++i)
        fields[first_shear + i].second[k] = shear[i] / points.size();
      for (unsigned int i = 0; i < components.size(); ++i)
        fields[first_strain + i].second[k] = strain[i] / points.size();
    }
  }

  template <int dim>
  Unit CellAverages<dim>::unit(const std::string &name) const
  {
    if (name.rfind("stress_", 0) == 0 || name == "von_mises_stress")
      return {"stress", "MPa"};
    if (name == "subdomain" || name == "level")
      return {"index", "1"};
    return {"strain", "1"}; // equivalent_plastic_strain, strain_*
  }

  template std::vector<std::pair<std::string, std::array<unsigned int, 2>>> tensor_components<2>();
  template std::vector<std::pair<std::string, std::array<unsigned int, 2>>> tensor_components<3>();
  template class YieldExcess<2>;
  template class CellAverages<2>;
  template class YieldExcess<3>;
  template class CellAverages<3>;

  namespace
  {
    template <int dim>
    std::unique_ptr<Postprocessor<dim>> make_yield_excess(const PostprocessorContext &c)
    {
      return std::make_unique<YieldExcess<dim>>(c.yield_stress);
    }

    template <int dim>
    std::unique_ptr<Postprocessor<dim>> make_cell_averages(const PostprocessorContext &)
    {
      return std::make_unique<CellAverages<dim>>();
    }
  } // namespace
} // namespace ausroll::io::postprocess

AUSROLL_REGISTER_POSTPROCESSOR(ausroll::io::postprocess::make_yield_excess,
                               "yield excess",
                               60,
                               "how far the stress lies outside the yield surface")

AUSROLL_REGISTER_POSTPROCESSOR(ausroll::io::postprocess::make_cell_averages,
                               "cell averages",
                               100,
                               "cell averages of stress and strain as VTU fields")
