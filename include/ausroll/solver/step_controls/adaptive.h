/**
 * @file adaptive.h
 * Step control `adaptive` (subsection `Loading/Adaptive`): the next step from the Newton
 * iterations and contact status changes of the last one.
 */
#pragma once

#include <ausroll/solver/step_control.h>

#include <memory>
#include <string>

namespace ausroll::solver
{
  /** Subsection `Adaptive` of `Loading`. */
  struct AdaptiveParameters : public StepControlParameters
  {
    unsigned int target_newton_iterations = 4; ///< `Target Newton iterations`
    unsigned int target_status_changes = 4;    ///< `Target status changes` (0: off)
    double       minimum_step_factor = 0.25;   ///< `Minimum step factor`: smallest shrink per step

    /** Declare the subsection's entries (the caller has entered it). */
    static void                  declare_parameters(dealii::ParameterHandler &prm);
    void                         parse(dealii::ParameterHandler &prm,
                                       const std::string        &path,
                                       const std::string        &input_directory) override;
    std::unique_ptr<StepControl> create(const double step_growth_factor) const override;
  };

  /**
   * `Step control = adaptive`: the size of the next step follows the last converged step
   * (step_factor()); after a cutback the factor is at most 1 and applies to the size taken,
   * otherwise to the size the stepper held (a step shortened to end on the nominal grid says
   * nothing about the size that works); never below the minimum nor above the nominal step.
   */
  class AdaptiveStepControl : public StepControl
  {
  public:
    /** The rule of @p parameters with `Loading/Step growth factor` @p step_growth_factor. */
    AdaptiveStepControl(const AdaptiveParameters &parameters, const double step_growth_factor);

    /**
     * Factor for the size of the step after a converged step that took @p newton_iterations
     * Newton iterations and changed @p status_changes contact statuses: shrink by target /
     * actual (not below `Minimum step factor`) when either exceeds its target, grow by `Step
     * growth factor` when the step was easy (at most half the target iterations and half the
     * target status changes), keep the size otherwise.
     */
    double step_factor(const unsigned int newton_iterations,
                       const unsigned int status_changes) const;

    double next_step_size(const StepOutcome          &outcome,
                          dealii::ConditionalOStream &detail_log) const override;

  private:
    const AdaptiveParameters parameters;
    const double             step_growth_factor;
  };
} // namespace ausroll::solver
