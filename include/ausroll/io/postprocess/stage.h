/**
 * @file stage.h
 * Postprocessor of the process stages (`Stages`): which stage a history row belongs to.
 */
#pragma once

#include <ausroll/io/postprocess/interface.h>

#include <vector>

namespace ausroll::io::postprocess
{
  /**
   * History column (runs with `Stages/Number of stages` > 0 only, the last column): `stage`, the
   * number k of `Stages/Stage k` whose interval (start, end] holds the row's time (the step that
   * ends a stage belongs to it; the initial row to stage 0). It follows from the time alone, so
   * a resumed run writes the same column.
   */
  template <int dim>
  class StageColumn : public Postprocessor<dim>
  {
  public:
    /** Stages ending at @p end_times (increasing; the last one is Loading/End time). */
    explicit StageColumn(const std::vector<double> &end_times);

    std::string name() const override { return "stage"; }

    void execute(const PostprocessInput<dim> &input, HistoryRow &row) const override;

    Unit unit(const std::string &name) const override;

    /** The stage of time @p t: the first whose end is not before t (1e-10 of the last end). */
    unsigned int stage_of(const double t) const;

  private:
    std::vector<double> end_times; ///< `Stages/Stage k/End time`
  };
} // namespace ausroll::io::postprocess
