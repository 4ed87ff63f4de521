/**
 * @file step_control.h
 * The step-size rule of the load stepper (`Loading/Step control`): the interface StepControl, the
 * parameters of a rule (StepControlParameters, one subsection of `Loading` per rule that has
 * entries) and their registry. The rules are in solver/step_controls/, one file pair each
 * (halving, adaptive), registered with AUSROLL_REGISTER_STEP_CONTROL.
 */
#pragma once

#include <ausroll/core/registry.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>

#include <memory>
#include <string>

namespace ausroll::solver
{
  struct LoadingParameters;

  /** What a step control sees of the step that has just converged. */
  struct StepOutcome
  {
    double       dt = 0.;               ///< the step size the stepper held before the step
    double       dt_taken = 0.;         ///< the size actually taken (after cutbacks, sub-steps)
    unsigned int newton_iterations = 0; ///< Newton iterations of the converged solve
    unsigned int cutbacks = 0;          ///< cutbacks of the step
    unsigned int status_changes = 0;    ///< contact status changes of the step
    double       nominal_dt = 0.;       ///< End time / Number of steps
    double       minimum_dt = 0.;       ///< `Minimum step fraction` of the nominal step
  };

  /**
   * A step-size rule (`Loading/Step control`): the size of the next step after a converged one.
   * The stepper then clips it to the nominal grid; a failing step is halved whatever the rule.
   */
  class StepControl
  {
  public:
    virtual ~StepControl() = default;

    /** The size of the next step after @p outcome; per-step details go to @p detail_log. */
    virtual double next_step_size(const StepOutcome          &outcome,
                                  dealii::ConditionalOStream &detail_log) const = 0;
  };

  /**
   * The parameters of one step control: the entries of its own subsection `Loading/<Name>`
   * (none for halving), registered in StepControlRegistry with AUSROLL_REGISTER_STEP_CONTROL at
   * the end of the rule's own `.cc` (solver/step_controls/).
   */
  class StepControlParameters : public RegisteredParameters
  {
  public:
    /** The rule; @p step_growth_factor is `Loading/Step growth factor`. */
    virtual std::unique_ptr<StepControl> create(const double step_growth_factor) const = 0;
  };

  /** The registry of the step controls (`Loading/Step control`). */
  using StepControlRegistry = Registry<StepControlParameters>;

  /** The rule of @p loading: made by `loading.step_control_parameters`, or by the registered
      defaults of `loading.step_control` when they are null. */
  std::unique_ptr<StepControl> create_step_control(const LoadingParameters &loading);
} // namespace ausroll::solver

/** Register the step-control parameters @p Class (see AUSROLL_REGISTER). */
#define AUSROLL_REGISTER_STEP_CONTROL(Class, name, subsection, description) \
  AUSROLL_REGISTER(::ausroll::solver::StepControlParameters, Class, name, subsection, description)
