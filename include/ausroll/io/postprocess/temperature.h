/**
 * @file temperature.h
 * Postprocessor of the temperature field of a thermal scene.
 */
#pragma once

#include <ausroll/io/postprocess/interface.h>

#include <deal.II/lac/trilinos_vector.h>

namespace ausroll::io::postprocess
{
  /**
   * History columns (thermal scenes only, appended after the mechanical ones):
   * - `T_min`, `T_max`, `T_mean`: smallest and largest nodal temperature, volume mean over the
   *   workpiece (reference volume), in the temperature unit of the input (degrees C in the shipped
   *   scenes);
   * - `heat_plastic`: plastic heating rate of the last step, int beta dW_p/dt dV (N mm/s = mW;
   *   2D: per the model's thickness, axisymmetric: the full circumference);
   * - `heat_condition_K`: heat flow into the workpiece through `Thermal/Condition K` over the last
   *   step (N mm/s; negative: the body loses heat), from the boundary integral (flux,
   *   convection) or the reaction of the prescribed temperature.
   * - `heat_die_K`: heat flow from `Contact/Die K` into the workpiece over the last step (N mm/s):
   *   contact conductance h_c (T_die - T) and the workpiece's part of the frictional heat.
   * VTU nodal fields: `temperature`, `temperature_rate` (of the last step, K/s) and in 3D
   * `thermal_strain_temperature` (T - T_ref, the temperature difference the thermal strain sees).
   */
  template <int dim>
  class TemperatureField : public Postprocessor<dim>
  {
  public:
    std::string name() const override { return "temperature"; }

    void execute(const PostprocessInput<dim> &input, HistoryRow &row) const override;

    void write_files(const PostprocessInput<dim> &input,
                     const std::string           &directory,
                     const unsigned int           counter) override;

    void nodal_fields(std::vector<NodalField> &fields) const override;
    Unit unit(const std::string &name) const override;

  private:
    bool                                  written = false; ///< fields below hold the last output
    dealii::TrilinosWrappers::MPI::Vector fields;          ///< on the displacement DoFs, ghosted
  };
} // namespace ausroll::io::postprocess
