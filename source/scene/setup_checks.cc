#include <ausroll/core/parse_utilities.h>
#include <ausroll/geometry/workpiece.h>
#include <ausroll/io/line_probe.h>
#include <ausroll/scene/setup_checks.h>
#include <ausroll/solver/linear_solver.h>

#include <deal.II/grid/grid_tools.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

namespace ausroll::scene
{
  template <int dim>
  void check_setup(const SceneParameters                    &parameters,
                   const dealii::Triangulation<dim>         &triangulation,
                   const mechanics::BoundaryConditions<dim> &boundary_conditions,
                   const contact::ContactOperator<dim>      &contact)
  {
    // Every boundary-id entry against the ids the mesh has.
    const auto &conditions = parameters.boundary_conditions.conditions;
    for (unsigned int i = 0; i < conditions.size(); ++i)
      geometry::require_boundary_ids(triangulation,
                                     {conditions[i].id},
                                     "Boundary conditions/Condition " + std::to_string(i)
                                         + "/Boundary id");
    for (unsigned int k = 0; k < parameters.contact.dies.size(); ++k)
      geometry::require_boundary_ids(triangulation,
                                     parameters.contact.dies[k].candidate_boundaries,
                                     "Contact/Die " + std::to_string(k) + "/Candidate boundaries");
    geometry::require_boundary_ids(triangulation,
                                   parse_unsigned_list(parameters.postprocess.reaction_boundaries,
                                                       "Postprocess/Reaction boundaries"),
                                   "Postprocess/Reaction boundaries");
    geometry::require_boundary_ids(triangulation,
                                   parameters.postprocess.boundary_profile.boundary_ids,
                                   "Postprocess/Boundary profile/Boundary ids");
    if (parameters.model.planar_model == mechanics::PlanarModel::axisymmetric)
      geometry::require_off_axis(triangulation, "Model/Planar model = axisymmetric");

    // Loads and dies at a bounded number of times.
    const std::vector<double> times = parameters.stages.sample_times(parameters.loading, 256);
    boundary_conditions.check_values(triangulation, times);
    const auto box = dealii::GridTools::compute_bounding_box(triangulation);
    if (contact.active())
      contact.check_dies(
          times, box.get_boundary_points().first.distance(box.get_boundary_points().second));
  }

  template <int dim>
  mechanics::MemoryEstimate check_sizes(const SceneParameters &parameters, const double n_cells)
  {
    const unsigned int degree = parameters.model.degree;
    geometry::require_dof_estimate(n_cells, degree, dim);
    // the samples of every line probe (checked here, before the memory estimate counts them)
    double                   probe_points = 0.;
    std::vector<std::string> probe_names;
    for (const io::LineProbeSpecification &probe :
         io::parse_line_probes(parameters.postprocess.line_probes, dim))
    {
      probe_points += probe.n_points;
      probe_names.push_back(probe.name);
    }
    for (const io::DepthProbeSpecification &probe :
         io::parse_depth_probes(parameters.postprocess.depth_probes, dim, probe_names))
      probe_points += probe.n_points;
    const double dofs = dim * n_cells * std::pow(double(degree), double(dim));
    const auto  &linear = parameters.solver.linear;
    const bool   direct = linear.type == solver::LinearSolverType::direct
                        || (linear.type == solver::LinearSolverType::automatic
                            && solver::automatic_solver_type<dim>(linear, dofs)
                                   == solver::LinearSolverType::direct);
    const mechanics::MemoryEstimate estimate = mechanics::estimate_memory(
        dim, n_cells, degree, parameters.model.quadrature_points, direct, probe_points);
    const geometry::GeometryParameters &g = parameters.geometry;
    mechanics::require_memory(
        estimate,
        "Geometry/Global refinements = " + std::to_string(g.global_refinements)
            + ", Geometry/Local refinements = " + std::to_string(g.local_refinements)
            + ", Model/Polynomial degree = " + std::to_string(degree)
            + ", Model/Quadrature points = " + std::to_string(parameters.model.quadrature_points)
            + (direct ? ", Solver/Linear solver/Type (direct)" : "")
            + (probe_points > 0. ? ", Postprocess/Line probes, Postprocess/Depth probes" : ""));
    return estimate;
  }

  template mechanics::MemoryEstimate check_sizes<2>(const SceneParameters &, const double);
  template mechanics::MemoryEstimate check_sizes<3>(const SceneParameters &, const double);
  template void                      check_setup(const SceneParameters &,
                                                 const dealii::Triangulation<2> &,
                                                 const mechanics::BoundaryConditions<2> &,
                                                 const contact::ContactOperator<2> &);
  template void                      check_setup(const SceneParameters &,
                                                 const dealii::Triangulation<3> &,
                                                 const mechanics::BoundaryConditions<3> &,
                                                 const contact::ContactOperator<3> &);
} // namespace ausroll::scene
