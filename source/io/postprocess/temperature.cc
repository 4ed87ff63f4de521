#include <ausroll/io/postprocess/standard_set.h>
#include <ausroll/io/postprocess/temperature.h>

#include <deal.II/dofs/dof_tools.h>

namespace ausroll::io::postprocess
{
  using namespace dealii;

  template <int dim>
  void TemperatureField<dim>::execute(const PostprocessInput<dim> &input, HistoryRow &row) const
  {
    if (input.thermal == nullptr)
      return;
    const std::array<double, 3> s = input.thermal->statistics();
    row.emplace_back("T_min", s[0]);
    row.emplace_back("T_max", s[1]);
    row.emplace_back("T_mean", s[2]);
    row.emplace_back("heat_plastic", input.thermal->balance.plastic_heat);
    for (unsigned int c = 0; c < input.thermal->balance.boundary_heat.size(); ++c)
      row.emplace_back("heat_condition_" + std::to_string(c),
                       input.thermal->balance.boundary_heat[c]);
    for (unsigned int k = 0; k < input.thermal->balance.die_heat.size(); ++k)
      row.emplace_back("heat_die_" + std::to_string(k), input.thermal->balance.die_heat[k]);
  }

  template <int dim>
  void TemperatureField<dim>::write_files(const PostprocessInput<dim> &input,
                                          const std::string           &directory,
                                          const unsigned int           counter)
  {
    (void)directory;
    (void)counter;
    written = input.thermal != nullptr;
    if (!written)
      return;
    // The temperature element is the scalar FE_Q of the displacement's degree on the same mesh:
    // thermal DoF i of a cell sits where the displacement DoFs of base index i sit.
    const thermal::ThermalSystem<dim> &thermal = *input.thermal;
    const MPI_Comm                     comm = input.dof_handler.get_communicator();
    const IndexSet                     owned = input.dof_handler.locally_owned_dofs();
    const IndexSet relevant = DoFTools::extract_locally_relevant_dofs(input.dof_handler);
    TrilinosWrappers::MPI::Vector        values(owned, comm);
    const auto                          &fe = input.dof_handler.get_fe();
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell()),
        thermal_dofs(thermal.fe.n_dofs_per_cell());
    const double reference = thermal.parameters.expansion.reference_temperature;
    for (const auto &cell : input.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
      {
        const typename DoFHandler<dim>::active_cell_iterator thermal_cell(
            &input.dof_handler.get_triangulation(),
            cell->level(),
            cell->index(),
            &thermal.dof_handler);
        cell->get_dof_indices(dofs);
        thermal_cell->get_dof_indices(thermal_dofs);
        for (unsigned int j = 0; j < dofs.size(); ++j)
        {
          if (!owned.is_element(dofs[j]))
            continue;
          const auto [component, i] = fe.system_to_component_index(j);
          const double T = thermal.temperature(thermal_dofs[i]);
          values(dofs[j]) = component == 0   ? T
                            : component == 1 ? thermal.temperature_rate(thermal_dofs[i])
                                             : T - reference;
        }
      }
    values.compress(VectorOperation::insert);
    fields.reinit(owned, relevant, comm);
    fields = values;
  }

  template <int dim>
  void TemperatureField<dim>::nodal_fields(std::vector<NodalField> &out) const
  {
    if (!written)
      return;
    std::vector<std::string> names{"temperature", "temperature_rate"};
    if (dim == 3)
      names.push_back("thermal_strain_temperature");
    out.emplace_back(names, &fields);
  }

  template <int dim>
  Unit TemperatureField<dim>::unit(const std::string &name) const
  {
    if (name == "temperature_rate")
      return {"temperature rate", "K/s"};
    if (name == "thermal_strain_temperature")
      return {"temperature difference", "K"};
    if (name.rfind("heat_", 0) == 0)
      return {"heat flow", "mW"};   // N mm/s
    return {"temperature", "degC"}; // T_min, T_max, T_mean, temperature
  }

  template class TemperatureField<2>;
  template class TemperatureField<3>;

  namespace
  {
    template <int dim>
    std::unique_ptr<Postprocessor<dim>> make_temperature_field(const PostprocessorContext &c)
    {
      if (!c.thermal)
        return nullptr;
      return std::make_unique<TemperatureField<dim>>();
    }
  } // namespace
} // namespace ausroll::io::postprocess

AUSROLL_REGISTER_POSTPROCESSOR(ausroll::io::postprocess::make_temperature_field,
                               "temperature",
                               120,
                               "temperature columns and fields of a thermal run")
