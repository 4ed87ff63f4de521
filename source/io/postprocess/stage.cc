#include <ausroll/io/postprocess/stage.h>
#include <ausroll/io/postprocess/standard_set.h>

#include <cmath>

namespace ausroll::io::postprocess
{
  template <int dim>
  StageColumn<dim>::StageColumn(const std::vector<double> &end_times)
      : end_times(end_times)
  {
  }

  template <int dim>
  unsigned int StageColumn<dim>::stage_of(const double t) const
  {
    const double tolerance = 1e-10 * std::abs(end_times.back());
    for (unsigned int k = 0; k < end_times.size(); ++k)
      if (end_times[k] - t >= -tolerance)
        return k;
    return end_times.size() - 1;
  }

  template <int dim>
  void StageColumn<dim>::execute(const PostprocessInput<dim> &input, HistoryRow &row) const
  {
    row.emplace_back("stage", stage_of(input.time));
  }

  template <int dim>
  Unit StageColumn<dim>::unit(const std::string &) const
  {
    return {"count", "1"};
  }

  template class StageColumn<2>;
  template class StageColumn<3>;

  namespace
  {
    template <int dim>
    std::unique_ptr<Postprocessor<dim>> make_stage_column(const PostprocessorContext &c)
    {
      if (c.stage_end_times.empty())
        return nullptr;
      return std::make_unique<StageColumn<dim>>(c.stage_end_times);
    }
  } // namespace
} // namespace ausroll::io::postprocess

AUSROLL_REGISTER_POSTPROCESSOR(ausroll::io::postprocess::make_stage_column,
                               "stage",
                               140,
                               "the stage column of a run with Stages")
