#include <ausroll/mechanics/distortion_check.h>

#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values.h>

#include <sstream>
#include <vector>

namespace ausroll::mechanics
{
  using namespace dealii;

  template <int dim>
  VolumeChangeRange<dim> volume_change_range(const Mapping<dim>                  &mapping,
                                             const DoFHandler<dim>               &dof_handler,
                                             const Quadrature<dim>               &quadrature,
                                             const PlanarKinematics<dim>         &kinematics,
                                             const TrilinosWrappers::MPI::Vector &u)
  {
    VolumeChangeRange<dim>           range;
    FEValues<dim>                    fe_values(mapping,
                            dof_handler.get_fe(),
                            quadrature,
                            update_values | update_gradients | update_quadrature_points);
    const FEValuesExtractors::Vector displacement(0);
    std::vector<Tensor<2, dim>>      grad_u(quadrature.size());
    std::vector<Tensor<1, dim>>      u_values(quadrature.size());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
      {
        fe_values.reinit(cell);
        fe_values[displacement].get_function_gradients(u, grad_u);
        fe_values[displacement].get_function_values(u, u_values);
        for (unsigned int q = 0; q < quadrature.size(); ++q)
        {
          const Point<dim> &X = fe_values.quadrature_point(q);
          const double J = determinant(kinematics.deformation_gradient(grad_u[q], u_values[q], X));
          if (J < range.min_J)
          {
            range.min_J = J;
            range.where_min = X;
          }
          if (J > range.max_J)
          {
            range.max_J = J;
            range.where_max = X;
          }
        }
      }
    // the extremes and their places from the rank that holds them
    const MPI_Comm     comm = dof_handler.get_communicator();
    const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    const double       global_min = Utilities::MPI::min(range.min_J, comm);
    const double       global_max = Utilities::MPI::max(range.max_J, comm);
    const unsigned int min_rank
        = Utilities::MPI::min(range.min_J == global_min ? rank : n_ranks, comm);
    const unsigned int max_rank
        = Utilities::MPI::min(range.max_J == global_max ? rank : n_ranks, comm);
    range.where_min = Utilities::MPI::broadcast(comm, range.where_min, min_rank);
    range.where_max = Utilities::MPI::broadcast(comm, range.where_max, max_rank);
    range.min_J = global_min;
    range.max_J = global_max;
    return range;
  }

  template <int dim>
  std::string distortion_warning(const VolumeChangeRange<dim> &range,
                                 const double                  limit,
                                 const unsigned int            step,
                                 const double                  time)
  {
    if (range.min_J >= limit && range.max_J <= 1. / limit)
      return "";
    const bool         low = range.min_J < limit;
    std::ostringstream msg;
    msg << "the mesh folds: J = det F = " << (low ? range.min_J : range.max_J)
        << " at the quadrature point (" << (low ? range.where_min : range.where_max)
        << ") (reference coordinates) in step " << step << ", t = " << time
        << " (Loading/Volume change limit = " << limit
        << "); forces from here on are not mesh-converged. Refine the mesh there (Geometry/"
           "Refinement point, Local refinements), let Adaptivity refine it, or let the folding "
           "surface touch the die (Contact/Die N/Candidate boundaries)";
    return msg.str();
  }

  template <int dim>
  bool DistortionMonitor<dim>::check(const Mapping<dim>                  &mapping,
                                     const DoFHandler<dim>               &dof_handler,
                                     const Quadrature<dim>               &quadrature,
                                     const PlanarKinematics<dim>         &kinematics,
                                     const TrilinosWrappers::MPI::Vector &u,
                                     const unsigned int                   step,
                                     const double                         time,
                                     ConditionalOStream                  &detail_log)
  {
    if (limit <= 0. || !first_warning.empty())
      return false;
    const VolumeChangeRange<dim> range
        = volume_change_range(mapping, dof_handler, quadrature, kinematics, u);
    detail_log << "  volume change J = det F in [" << range.min_J << " at (" << range.where_min
               << "), " << range.max_J << " at (" << range.where_max << ")]" << std::endl;
    first_warning = distortion_warning(range, limit, step, time);
    return !first_warning.empty();
  }

  template class DistortionMonitor<2>;
  template class DistortionMonitor<3>;
  template struct VolumeChangeRange<2>;
  template struct VolumeChangeRange<3>;
  template VolumeChangeRange<2> volume_change_range(const Mapping<2> &,
                                                    const DoFHandler<2> &,
                                                    const Quadrature<2> &,
                                                    const PlanarKinematics<2> &,
                                                    const TrilinosWrappers::MPI::Vector &);
  template VolumeChangeRange<3> volume_change_range(const Mapping<3> &,
                                                    const DoFHandler<3> &,
                                                    const Quadrature<3> &,
                                                    const PlanarKinematics<3> &,
                                                    const TrilinosWrappers::MPI::Vector &);
  template std::string
  distortion_warning(const VolumeChangeRange<2> &, const double, const unsigned int, const double);
  template std::string
  distortion_warning(const VolumeChangeRange<3> &, const double, const unsigned int, const double);
} // namespace ausroll::mechanics
