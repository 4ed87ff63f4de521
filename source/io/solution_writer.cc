#include <ausroll/io/solution_writer.h>

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/mpi.h>
#include <deal.II/fe/mapping_q_eulerian.h>
#include <deal.II/numerics/data_out.h>

#include <cstdio>
#include <fstream>

namespace ausroll::io
{
  using namespace dealii;

  template <int dim>
  SolutionWriter<dim>::SolutionWriter(const std::string &directory, const MPI_Comm comm)
      : directory(directory)
      , comm(comm)
  {
  }

  template <int dim>
  void SolutionWriter<dim>::set_records(const std::vector<std::pair<double, std::string>> &records)
  {
    time_series = records;
  }

  template <int dim>
  std::string SolutionWriter<dim>::write(const unsigned int                   counter,
                                         const double                         time,
                                         const DoFHandler<dim>               &dof_handler,
                                         const Mapping<dim>                  &mapping,
                                         const TrilinosWrappers::MPI::Vector &solution,
                                         const std::vector<CellField>        &cell_fields,
                                         const std::vector<NodalField>       &nodal_fields,
                                         const bool                           deformed)
  {
    DataOut<dim> data_out;
    data_out.attach_dof_handler(dof_handler);
    const std::vector<std::string> names(dim, "displacement");
    const std::vector<DataComponentInterpretation::DataComponentInterpretation> interpretation(
        dim, DataComponentInterpretation::component_is_part_of_vector);
    data_out.add_data_vector(solution, names, DataOut<dim>::type_dof_data, interpretation);
    for (const NodalField &field : nodal_fields)
      data_out.add_data_vector(
          *field.second,
          field.first,
          DataOut<dim>::type_dof_data,
          std::vector<DataComponentInterpretation::DataComponentInterpretation>(
              dim, DataComponentInterpretation::component_is_scalar));
    for (const CellField &field : cell_fields)
      data_out.add_data_vector(field.second, field.first, DataOut<dim>::type_cell_data);

    const unsigned int degree = dof_handler.get_fe().degree;
    if (deformed)
    {
      const MappingQEulerian<dim, TrilinosWrappers::MPI::Vector> moved(
          degree, dof_handler, solution);
      data_out.build_patches(moved, degree, DataOut<dim>::curved_inner_cells);
    }
    else
      data_out.build_patches(mapping, degree, DataOut<dim>::curved_inner_cells);

    DataOutBase::VtkFlags flags;
    flags.time = time;
    flags.cycle = counter;
    flags.write_higher_order_cells = false;
    data_out.set_flags(flags);
    const std::string pvtu
        = data_out.write_vtu_with_pvtu_record(directory + "/", "solution", counter, comm, 4);

    time_series.emplace_back(time, pvtu);
    if (Utilities::MPI::this_mpi_process(comm) == 0)
    {
      const std::string pvd = directory + "/solution.pvd";
      const std::string tmp = pvd + ".tmp";
      {
        std::ofstream out(tmp);
        DataOutBase::write_pvd_record(out, time_series);
      }
      std::rename(tmp.c_str(), pvd.c_str());
    }
    return pvtu;
  }

  template class SolutionWriter<2>;
  template class SolutionWriter<3>;
} // namespace ausroll::io
