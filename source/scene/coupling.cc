/**
 * @file coupling.cc
 * The temperature field's members of Scene: how the heat equation is coupled to the mechanics
 * (isothermal split per load step: the mechanical step at the temperature of its start, then the
 * heat equation over the converged step with its plastic heating; ThermalExpansionModel reads the
 * temperature the field writes into the material points).
 */
#include <ausroll/scene/scene.h>

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
  void Scene<dim>::thermal_step(const solver::LoadStep &step)
  {
    TimerOutput::Scope scope(*timer, "thermal");
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

  template void Scene<2>::setup_thermal();
  template void Scene<2>::initialize_temperature();
  template void Scene<2>::thermal_step(const solver::LoadStep &);
  template void Scene<3>::setup_thermal();
  template void Scene<3>::initialize_temperature();
  template void Scene<3>::thermal_step(const solver::LoadStep &);
} // namespace ausroll::scene
