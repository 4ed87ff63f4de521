#include <ausroll/core/exceptions.h>
#include <ausroll/io/solution_writer.h>

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/mpi.h>
#include <deal.II/fe/mapping_q_eulerian.h>
#include <deal.II/numerics/data_out.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
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
    // Before anything of this output is written (rank 0 writes the record; an error found there
    // alone ends every rank, see main.cc).
    if (Utilities::MPI::this_mpi_process(comm) == 0)
    {
      std::error_code ec;
      if (std::filesystem::is_directory(directory + "/solution.pvd", ec))
        throw InputError("Output/Directory: cannot write '" + directory
                         + "/solution.pvd': a directory of that name is in the way; remove it");
    }
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
    std::string pvtu;
    try
    {
      pvtu = data_out.write_vtu_with_pvtu_record(directory + "/", "solution", counter, comm, 4);
    }
    catch (const std::exception &)
    {
      // deal.II reports a failed write (full disk, a directory in the way) as an internal
      // assertion; say which files could not be written.
      throw RunFailure("cannot write the solution files '" + directory + "/solution_"
                       + Utilities::int_to_string(counter, 4)
                       + "*.vtu' (disk full, no permission, or a directory of that name?)");
    }

    time_series.emplace_back(time, pvtu);
    if (Utilities::MPI::this_mpi_process(comm) == 0)
    {
      const std::string pvd = directory + "/solution.pvd";
      const std::string tmp = pvd + ".tmp";
      std::error_code   ec;
      {
        std::ofstream out(tmp);
        DataOutBase::write_pvd_record(out, time_series);
        out.close();
        if (!out)
        {
          std::filesystem::remove(tmp, ec);
          throw RunFailure("cannot write '" + tmp + "' (disk full or no permission?)");
        }
      }
      if (std::rename(tmp.c_str(), pvd.c_str()) != 0)
      {
        const std::string reason = std::strerror(errno);
        std::filesystem::remove(tmp, ec);
        throw RunFailure("cannot replace '" + pvd + "' by '" + tmp + "': " + reason);
      }
    }
    return pvtu;
  }

  template class SolutionWriter<2>;
  template class SolutionWriter<3>;
} // namespace ausroll::io
