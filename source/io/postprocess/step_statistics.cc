#include <ausroll/io/postprocess/standard_set.h>
#include <ausroll/io/postprocess/step_statistics.h>

namespace ausroll::io::postprocess
{
  template <int dim>
  StepStatistics<dim>::StepStatistics(const double end_time, const bool time_in_seconds)
      : end_time(end_time)
      , time_in_seconds(time_in_seconds)
  {
  }

  template <int dim>
  void StepStatistics<dim>::execute(const PostprocessInput<dim> &input, HistoryRow &row) const
  {
    row.emplace_back("step", input.step);
    row.emplace_back("time", input.time);
    row.emplace_back("load_factor", input.time / end_time);
    row.emplace_back("newton_iterations", input.newton_iterations);
    row.emplace_back("cutbacks", input.cutbacks);
    row.emplace_back("dofs", input.dof_handler.n_dofs());
    row.emplace_back("cells", input.dof_handler.get_triangulation().n_global_active_cells());
    row.emplace_back("wall_seconds", input.wall_seconds);
  }

  template <int dim>
  void AppliedPressures<dim>::execute(const PostprocessInput<dim> &input, HistoryRow &row) const
  {
    for (const auto &p : input.boundary_conditions.pressure_values(input.time))
      row.push_back(p);
  }

  template <int dim>
  Unit StepStatistics<dim>::unit(const std::string &column) const
  {
    if (column == "time")
      return time_in_seconds ? Unit{"time", "s"} : Unit{"pseudo-time", "-"};
    if (column == "wall_seconds")
      return {"wall time", "s"};
    if (column == "load_factor")
      return {"dimensionless", "1"};
    return {"count", "1"}; // step, newton_iterations, cutbacks, dofs, cells
  }

  template class StepStatistics<2>;
  template class AppliedPressures<2>;
  template class StepStatistics<3>;
  template class AppliedPressures<3>;

  namespace
  {
    template <int dim>
    std::unique_ptr<Postprocessor<dim>> make_step_statistics(const PostprocessorContext &c)
    {
      return std::make_unique<StepStatistics<dim>>(c.end_time, c.thermal);
    }

    template <int dim>
    std::unique_ptr<Postprocessor<dim>> make_applied_pressures(const PostprocessorContext &)
    {
      return std::make_unique<AppliedPressures<dim>>();
    }
  } // namespace
} // namespace ausroll::io::postprocess

AUSROLL_REGISTER_POSTPROCESSOR(ausroll::io::postprocess::make_step_statistics,
                               "step statistics",
                               10,
                               "step, time, load factor, iterations and cutbacks of each step")

AUSROLL_REGISTER_POSTPROCESSOR(ausroll::io::postprocess::make_applied_pressures,
                               "applied pressures",
                               20,
                               "the pressure of every pressure boundary condition")
