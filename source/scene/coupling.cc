/**
 * @file coupling.cc
 * The temperature field's members of Scene: how the heat equation is coupled to the mechanics
 * (isothermal split per load step: the mechanical step at the temperature of its start, then the
 * heat equation over the converged step with its plastic heating; ThermalExpansionModel reads the
 * temperature the field writes into the material points).
 */
#include <ausroll/core/exceptions.h>
#include <ausroll/scene/scene.h>

#include <deal.II/base/function_parser.h>
#include <deal.II/fe/fe_values.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace ausroll::scene
{
  using namespace dealii;

  template <int dim>
  void Scene<dim>::setup_thermal()
  {
    if (!parameters.thermal.enabled)
      return;
    typename thermal::ThermalSystem<dim>::Kinematics geometry;
    geometry.volume_factor = [this](const Point<dim> &x) { return kinematics.volume_factor(x); };
    if (!model->is_small_strain())
      geometry.deformation_gradient
          = [this](const Tensor<2, dim> &grad_u, const Tensor<1, dim> &u, const Point<dim> &x)
      { return kinematics.deformation_gradient(grad_u, u, x); };
    thermal = std::make_unique<thermal::ThermalSystem<dim>>(parameters.thermal,
                                                            system.triangulation,
                                                            system.mapping,
                                                            parameters.model.degree,
                                                            assembler->quadrature(),
                                                            geometry,
                                                            contact.n_dies(),
                                                            comm);
    thermal->check_die_temperatures(parameters.loading.end_time);
    // every stage's expressions parsed now, so that an error comes before the run; then stage 0
    const auto &stages = parameters.stages.stages;
    for (unsigned int k = stages.size(); k-- > 0;)
      thermal->set_conditions(stages[k].thermal_conditions,
                              "Stages/Stage " + std::to_string(k) + "/Thermal condition values");
    thermal->setup();
  }

  template <int dim>
  void Scene<dim>::initialize_temperature()
  {
    if (!thermal)
      return;
    thermal->initialize();
    thermal->set_point_temperatures(system.material_points, true);
    ++system.assembly_cache.state;
  }

  template <int dim>
  void Scene<dim>::initialize_carbon()
  {
    const std::string   entry = "Phases/Carbon content";
    FunctionParser<dim> carbon(1);
    try
    {
      carbon.initialize(dim == 2 ? "x,y" : "x,y,z",
                        parameters.phases.carbon_content,
                        std::map<std::string, double>{{"pi", numbers::PI}});
    }
    catch (...)
    {
      throw InputError(entry + ": cannot parse '" + parameters.phases.carbon_content
                       + "' (variables: x, y" + (dim == 3 ? ", z)" : ")"));
    }
    FEValues<dim> points(
        system.mapping, system.fe, assembler->quadrature(), update_quadrature_points);
    double lowest = std::numeric_limits<double>::max(), highest = -lowest;
    for (const auto &cell : system.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
      {
        points.reinit(cell);
        const auto states = system.material_points.get_data(cell);
        for (unsigned int q = 0; q < states.size(); ++q)
        {
          const double C = carbon.value(points.quadrature_point(q));
          lowest = std::isnan(C) ? -std::numeric_limits<double>::infinity() : std::min(lowest, C);
          highest = std::max(highest, C);
          states[q]->committed.carbon = states[q]->trial.carbon = C;
          states[q]->committed.martensite = states[q]->trial.martensite = 0.;
          states[q]->committed.bainite = states[q]->trial.bainite = 0.;
        }
      }
    // collective, so that every rank stops with the same message
    lowest = Utilities::MPI::min(lowest, comm);
    highest = Utilities::MPI::max(highest, comm);
    if (!(lowest >= 0. && highest <= 2.1))
    {
      std::ostringstream range;
      range << lowest << " to " << highest;
      throw InputError(entry + ": '" + parameters.phases.carbon_content + "' ranges from "
                       + range.str() + " wt% over the workpiece, outside 0 to 2.1 (steels)");
    }
    ++system.assembly_cache.state;
  }

  template <int dim>
  void Scene<dim>::thermal_step(const solver::LoadStep &step)
  {
    TimerOutput::Scope scope(*timer, "thermal");
    if (parameters.stages.declared())
    {
      const unsigned int k = parameters.stages.stage_at(step.t_start);
      thermal->set_conditions(parameters.stages.stages[k].thermal_conditions,
                              "Stages/Stage " + std::to_string(k) + "/Thermal condition values");
    }
    thermal->solve_step(step.time,
                        step.time - step.t_start,
                        system.dof_handler,
                        system.solution_ghosted,
                        system.material_points,
                        contact.active()
                            ? contact.heat_contacts()
                            : std::vector<typename contact::ContactOperator<dim>::HeatContact>());
    thermal->set_point_temperatures(system.material_points, false);
    ++system.assembly_cache.state;
  }

  template <int dim>
  solver::NewtonResult Scene<dim>::iterate_coupling(const solver::NewtonResult &first)
  {
    if (parameters.coupling.iterations <= 1 || !first.converged)
      return first;
    solver::NewtonResult total = first;
    solver::LoadStep     step;
    step.t_start = step_start_time;
    step.time = time;
    for (unsigned int k = 1;; ++k)
    {
      thermal_step(step);
      thermal_current = true;
      newton_log << "  coupling: heat solve " << k << ", largest temperature change "
                 << thermal->last_change << std::endl;
      if (thermal->last_change <= parameters.coupling.tolerance
          || k >= parameters.coupling.iterations)
        return total;
      // the mechanical step again, at the new temperature
      thermal->set_point_temperatures(system.material_points, true);
      ++system.assembly_cache.state;
      const solver::NewtonResult again = newton.solve(*equilibrium, newton_log);
      thermal_current = false;
      total.iterations += again.iterations;
      total.outer_passes += again.outer_passes;
      total.linear_iterations += again.linear_iterations;
      total.residual = again.residual;
      if (!again.converged)
      {
        total.converged = false;
        total.reason = "coupling iteration " + std::to_string(k) + ": " + again.reason;
        return total;
      }
    }
  }

  template <int dim>
  void Scene<dim>::restore_temperature()
  {
    if (parameters.coupling.iterations <= 1)
      return; // the field changes only when a step is accepted
    thermal->restore();
    thermal->set_point_temperatures(system.material_points, true);
    ++system.assembly_cache.state;
    thermal_current = false;
  }

  template void                 Scene<2>::setup_thermal();
  template void                 Scene<2>::initialize_temperature();
  template void                 Scene<2>::initialize_carbon();
  template void                 Scene<2>::thermal_step(const solver::LoadStep &);
  template solver::NewtonResult Scene<2>::iterate_coupling(const solver::NewtonResult &);
  template void                 Scene<2>::restore_temperature();
  template solver::NewtonResult Scene<3>::iterate_coupling(const solver::NewtonResult &);
  template void                 Scene<3>::restore_temperature();
  template void                 Scene<3>::setup_thermal();
  template void                 Scene<3>::initialize_temperature();
  template void                 Scene<3>::initialize_carbon();
  template void                 Scene<3>::thermal_step(const solver::LoadStep &);
} // namespace ausroll::scene
