/**
 * @file step_statistics.h
 * History basics: step, time, load factor, Newton iterations, cutbacks, mesh size, wall time.
 */
#pragma once

#include <ausroll/io/postprocess/interface.h>

namespace ausroll::io::postprocess
{
  /**
   * History columns `step` (converged steps so far; count, 1), `time` (pseudo-time t, the unit
   * of the `.prm`'s expressions: -; time in s in thermal scenes), `load_factor` (t / `Loading/End
   * time`; 1), `newton_iterations` and `cutbacks` (of the last step; counts, 1), `dofs`, `cells`
   * (global; counts, 1) and `wall_seconds` (s, since the start of the process; not reproducible,
   * left out of regression lines and history comparisons).
   */
  template <int dim>
  class StepStatistics : public Postprocessor<dim>
  {
  public:
    /** With @p end_time = `Loading/End time` (load factor 1); @p time_in_seconds: the load
        parameter is time in s (thermal scenes), else a pseudo-time. */
    explicit StepStatistics(const double end_time, const bool time_in_seconds = false);
    std::string name() const override { return "step statistics"; }
    void        execute(const PostprocessInput<dim> &input, HistoryRow &row) const override;
    Unit        unit(const std::string &column) const override;

  private:
    double end_time;
    bool   time_in_seconds;
  };

  /**
   * History columns of the pressure loads: one per `Boundary conditions/Condition N` of type
   * pressure, named and valued by mechanics::BoundaryConditions::pressure_values()
   * (`pressure_<id>`, the expression evaluated at the origin at the current time; stress, MPa).
   */
  template <int dim>
  class AppliedPressures : public Postprocessor<dim>
  {
  public:
    std::string name() const override { return "applied pressures"; }
    void        execute(const PostprocessInput<dim> &input, HistoryRow &row) const override;
    Unit        unit(const std::string &column) const override
    {
      (void)column;
      return {"stress", "MPa"};
    }
  };
} // namespace ausroll::io::postprocess
