#include <ausroll/solver/step_controls/halving.h>

#include <algorithm>

namespace ausroll::solver
{
  HalvingStepControl::HalvingStepControl(const double step_growth_factor)
      : step_growth_factor(step_growth_factor)
  {
  }

  double HalvingStepControl::next_step_size(const StepOutcome &outcome,
                                            dealii::ConditionalOStream &) const
  {
    return outcome.cutbacks > 0 ? outcome.dt_taken
                                : std::min(outcome.nominal_dt, outcome.dt * step_growth_factor);
  }

  std::unique_ptr<StepControl> HalvingParameters::create(const double step_growth_factor) const
  {
    return std::make_unique<HalvingStepControl>(step_growth_factor);
  }
} // namespace ausroll::solver

AUSROLL_REGISTER_STEP_CONTROL(ausroll::solver::HalvingParameters,
                              "halving",
                              "",
                              "a failing step is halved (Maximum cutbacks), every later step "
                              "grows by Step growth factor up to the nominal size")
