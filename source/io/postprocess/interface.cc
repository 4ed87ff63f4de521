#include <ausroll/io/postprocess/interface.h>

#include <deal.II/base/mpi.h>

#include <fstream>
#include <map>
#include <stdexcept>

namespace ausroll::io
{
  namespace
  {
    /** Write @p file on rank 0 of @p comm: @p header, then "name,quantity,unit" per entry. */
    void write_units(const std::string                               &file,
                     const std::string                               &header,
                     const std::vector<std::pair<std::string, Unit>> &units,
                     const MPI_Comm                                   comm)
    {
      if (dealii::Utilities::MPI::this_mpi_process(comm) != 0)
        return;
      std::ofstream out(file);
      out << header << '\n';
      for (const auto &[name, unit] : units)
        out << name << ',' << (unit.quantity.empty() ? "unknown" : unit.quantity) << ','
            << (unit.unit.empty() ? "unknown" : unit.unit) << '\n';
    }
  } // namespace

  template <int dim>
  PostprocessorSet<dim>::PostprocessorSet(const OutputParameters &output, const MPI_Comm comm)
      : output(output)
      , comm(comm)
  {
  }

  template <int dim>
  void PostprocessorSet<dim>::add(std::unique_ptr<Postprocessor<dim>> postprocessor)
  {
    members.push_back(std::move(postprocessor));
  }

  template <int dim>
  void PostprocessorSet<dim>::initialize(const PostprocessInput<dim> &input)
  {
    for (const auto &p : members)
      p->initialize(input);
  }

  template <int dim>
  HistoryRow PostprocessorSet<dim>::history_row(const PostprocessInput<dim> &input)
  {
    HistoryRow                                row;
    std::map<std::string, std::string>        producer; // column -> postprocessor
    std::vector<std::pair<std::string, Unit>> units;
    for (const auto &p : members)
    {
      const std::size_t first = row.size();
      p->execute(input, row);
      for (std::size_t i = first; i < row.size(); ++i)
      {
        const auto [where, inserted] = producer.emplace(row[i].first, p->name());
        if (!inserted)
          throw std::logic_error("history column '" + row[i].first + "' is produced twice (by "
                                 + where->second + " and by " + p->name() + ")");
        units.emplace_back(row[i].first, p->unit(row[i].first));
      }
    }
    if (!history_units_written && !directory.empty())
    {
      write_units(directory + "/history_units.csv", "column,quantity,unit", units, comm);
      history_units_written = true;
    }
    return row;
  }

  template <int dim>
  void PostprocessorSet<dim>::open_vtu_writer(const std::string &directory)
  {
    writer = std::make_unique<SolutionWriter<dim>>(directory, comm);
    this->directory = directory;
  }

  template <int dim>
  void PostprocessorSet<dim>::write_output(const PostprocessInput<dim> &input,
                                           const std::string           &directory,
                                           const unsigned int           counter)
  {
    for (const auto &p : members)
      p->write_files(input, directory, counter);
    if (!output.write_vtu)
      return;
    if (!writer)
      throw std::logic_error("PostprocessorSet::write_output() before open_vtu_writer()");
    std::vector<CellField>                    cells;
    std::vector<NodalField>                   nodes;
    std::vector<std::pair<std::string, Unit>> units{{"displacement", {"length", "mm"}}};
    for (const auto &p : members)
    {
      const std::size_t first_cell = cells.size(), first_node = nodes.size();
      p->cell_fields(input, cells);
      p->nodal_fields(nodes);
      for (std::size_t i = first_cell; i < cells.size(); ++i)
        units.emplace_back(cells[i].first, p->unit(cells[i].first));
      for (std::size_t i = first_node; i < nodes.size(); ++i)
        for (const std::string &name : nodes[i].first)
          units.emplace_back(name, p->unit(name));
    }
    if (!vtu_units_written)
    {
      write_units(directory + "/solution_units.csv", "array,quantity,unit", units, comm);
      vtu_units_written = true;
    }
    writer->write(counter,
                  input.time,
                  input.dof_handler,
                  input.mapping,
                  input.solution,
                  cells,
                  nodes,
                  output.deformed_mesh);
  }

  template <int dim>
  const std::vector<std::pair<double, std::string>> &PostprocessorSet<dim>::vtu_records() const
  {
    static const std::vector<std::pair<double, std::string>> none;
    return writer ? writer->records() : none;
  }

  template <int dim>
  void
  PostprocessorSet<dim>::set_vtu_records(const std::vector<std::pair<double, std::string>> &records)
  {
    if (!writer)
      throw std::logic_error("PostprocessorSet::set_vtu_records() before open_vtu_writer()");
    writer->set_records(records);
  }

  template class PostprocessorSet<2>;
  template class PostprocessorSet<3>;
} // namespace ausroll::io
