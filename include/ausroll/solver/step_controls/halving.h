/**
 * @file halving.h
 * Step control `halving` (no subsection): the size that worked after a cutback, else growth back
 * to the nominal step.
 */
#pragma once

#include <ausroll/solver/step_control.h>

#include <memory>

namespace ausroll::solver
{
  /**
   * `Step control = halving`: after a step that was cut back, the next step keeps the size that
   * converged; otherwise it grows by `Step growth factor`, to at most the nominal step.
   */
  class HalvingStepControl : public StepControl
  {
  public:
    /** @p step_growth_factor: `Loading/Step growth factor`. */
    explicit HalvingStepControl(const double step_growth_factor);

    double next_step_size(const StepOutcome          &outcome,
                          dealii::ConditionalOStream &detail_log) const override;

  private:
    const double step_growth_factor;
  };

  /** Parameters of `halving`: none. */
  struct HalvingParameters : public StepControlParameters
  {
    static void                  declare_parameters(dealii::ParameterHandler &) {}
    std::unique_ptr<StepControl> create(const double step_growth_factor) const override;
  };
} // namespace ausroll::solver
