#include <ausroll/core/exceptions.h>
#include <ausroll/core/parse_utilities.h>
#include <ausroll/io/owned_cell_around_point.h>
#include <ausroll/io/postprocess/monitor_points.h>
#include <ausroll/io/postprocess/standard_set.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>

#include <sstream>

namespace ausroll::io::postprocess
{
  using namespace dealii;

  template <int dim>
  MonitorPoints<dim>::MonitorPoints(const std::string &specification)
      : specification(specification)
  {
  }

  template <int dim>
  void MonitorPoints<dim>::initialize(const PostprocessInput<dim> &input)
  {
    const MPI_Comm     comm = input.dof_handler.get_communicator();
    const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    const std::string  entry = "Postprocess/Monitor points";
    points.clear();
    for (const auto &[name, position] : parse_named_points<dim>(specification, entry))
    {
      Point m;
      m.name = name;
      m.position = position;
      unsigned int found_rank = n_ranks;
      if (const auto found = owned_cell_around_point(input.mapping, input.dof_handler, position))
      {
        m.cell = found->first;
        m.unit_point = found->second;
        found_rank = rank;
      }
      const unsigned int owner = Utilities::MPI::min(found_rank, comm);
      if (owner == n_ranks)
      {
        std::ostringstream msg;
        msg << entry << ": point '" << name << "' (" << position << ") is outside the workpiece";
        throw InputError(msg.str());
      }
      m.local = owner == rank;
      points.push_back(m);
    }
  }

  template <int dim>
  void MonitorPoints<dim>::execute(const PostprocessInput<dim> &input, HistoryRow &row) const
  {
    const MPI_Comm comm = input.dof_handler.get_communicator();
    for (const Point &m : points)
    {
      Tensor<1, dim> u;
      if (m.local)
      {
        const Quadrature<dim> q(m.unit_point);
        FEValues<dim> fe_values(input.mapping, input.dof_handler.get_fe(), q, update_values);
        fe_values.reinit(m.cell);
        std::vector<Tensor<1, dim>> values(1);
        fe_values[FEValuesExtractors::Vector(0)].get_function_values(input.solution, values);
        u = values[0];
      }
      for (unsigned int d = 0; d < dim; ++d)
        row.emplace_back(m.name + "_u" + std::string(1, "xyz"[d]), Utilities::MPI::sum(u[d], comm));
    }
  }

  template class MonitorPoints<2>;
  template class MonitorPoints<3>;

  namespace
  {
    template <int dim>
    std::unique_ptr<Postprocessor<dim>> make_monitor_points(const PostprocessorContext &c)
    {
      return std::make_unique<MonitorPoints<dim>>(c.postprocess.monitor_points);
    }
  } // namespace
} // namespace ausroll::io::postprocess

AUSROLL_REGISTER_POSTPROCESSOR(ausroll::io::postprocess::make_monitor_points,
                               "monitor points",
                               30,
                               "displacements at the Monitor points")
