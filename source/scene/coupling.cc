/**
 * @file coupling.cc
 * The temperature field's members of Scene: how the heat equation is coupled to the mechanics
 * (isothermal split per load step: the mechanical step at the temperature of its start, then the
 * heat equation over the converged step with its plastic heating; ThermalExpansionModel reads the
 * temperature the field writes into the material points).
 */
#include <ausroll/core/exceptions.h>
#include <ausroll/material/carbon_profile.h>
#include <ausroll/material/phase_transformation_model.h>
#include <ausroll/scene/scene.h>

#include <algorithm>

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
  void Scene<dim>::initialize_phases()
  {
    // the depth is measured from Phases/Case boundaries, by default from the surface the dies
    // touch (their Candidate boundaries)
    std::vector<unsigned int> case_boundaries = parameters.phases.case_boundaries;
    if (case_boundaries.empty())
      for (const auto &die : parameters.contact.dies)
        for (const unsigned int id : die.candidate_boundaries)
          if (std::find(case_boundaries.begin(), case_boundaries.end(), id)
              == case_boundaries.end())
            case_boundaries.push_back(id);
    const material::CarbonProfile<dim> profile(parameters.phases.carbon_content,
                                               system.triangulation,
                                               case_boundaries,
                                               parameters.phases.input_directory);
    material::initialize_carbon(profile,
                                parameters.phases.carbon_content,
                                system.mapping,
                                system.fe,
                                assembler->quadrature(),
                                system.dof_handler,
                                system.material_points,
                                comm);
    // the phases at t = 0 follow from the carbon content and the initial temperature
    initialize_temperature();
    material::initialize_phase_state(
        parameters.phases, system.triangulation, system.material_points, comm);
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
  template void                 Scene<2>::initialize_phases();
  template void                 Scene<2>::thermal_step(const solver::LoadStep &);
  template solver::NewtonResult Scene<2>::iterate_coupling(const solver::NewtonResult &);
  template void                 Scene<2>::restore_temperature();
  template solver::NewtonResult Scene<3>::iterate_coupling(const solver::NewtonResult &);
  template void                 Scene<3>::restore_temperature();
  template void                 Scene<3>::setup_thermal();
  template void                 Scene<3>::initialize_temperature();
  template void                 Scene<3>::initialize_phases();
  template void                 Scene<3>::thermal_step(const solver::LoadStep &);
} // namespace ausroll::scene
