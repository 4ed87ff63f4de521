#include <ausroll/solver/step_controls/adaptive.h>

#include <algorithm>

namespace ausroll::solver
{
  using namespace dealii;

  void AdaptiveParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Target Newton iterations",
                      "4",
                      Patterns::Integer(1, 100),
                      "Newton iterations per step aimed at. Steps grow after at most half of it "
                      "and keep their size up to it, so they settle at half the target plus one "
                      "(4: 3 iterations per step).");
    prm.declare_entry("Target status changes",
                      "4",
                      Patterns::Integer(0, 100000),
                      "Contact status changes (nodes closing, opening, switching stick/slip) per "
                      "step aimed at; 0: not used.");
    prm.declare_entry("Minimum step factor",
                      "0.25",
                      Patterns::Double(0.01, 1.),
                      "The next step is at least this fraction of the last one.");
  }

  void AdaptiveParameters::parse(ParameterHandler &prm, const std::string &, const std::string &)
  {
    target_newton_iterations = prm.get_integer("Target Newton iterations");
    target_status_changes = prm.get_integer("Target status changes");
    minimum_step_factor = prm.get_double("Minimum step factor");
  }

  std::unique_ptr<StepControl> AdaptiveParameters::create(const double step_growth_factor) const
  {
    return std::make_unique<AdaptiveStepControl>(*this, step_growth_factor);
  }

  AdaptiveStepControl::AdaptiveStepControl(const AdaptiveParameters &parameters,
                                           const double              step_growth_factor)
      : parameters(parameters)
      , step_growth_factor(step_growth_factor)
  {
  }

  double AdaptiveStepControl::step_factor(const unsigned int newton_iterations,
                                          const unsigned int status_changes) const
  {
    const unsigned int target_newton_iterations = parameters.target_newton_iterations;
    const unsigned int target_status_changes = parameters.target_status_changes;
    double             factor = 1.;
    if (newton_iterations > target_newton_iterations)
      factor = double(target_newton_iterations) / newton_iterations;
    if (target_status_changes > 0 && status_changes > target_status_changes)
      factor = std::min(factor, double(target_status_changes) / status_changes);
    if (factor < 1.)
      return std::max(factor, parameters.minimum_step_factor);
    const bool easy_iterations = 2 * newton_iterations <= target_newton_iterations;
    const bool easy_contact
        = target_status_changes == 0 || 2 * status_changes <= target_status_changes;
    return easy_iterations && easy_contact ? step_growth_factor : 1.;
  }

  double AdaptiveStepControl::next_step_size(const StepOutcome          &outcome,
                                             dealii::ConditionalOStream &detail_log) const
  {
    // From the step actually taken after a cutback, else from the size asked for (a step
    // shortened to end on the nominal grid says nothing about the size that works).
    double factor = step_factor(outcome.newton_iterations, outcome.status_changes);
    if (outcome.cutbacks > 0)
      factor = std::min(factor, 1.);
    const double next = std::clamp((outcome.cutbacks > 0 ? outcome.dt_taken : outcome.dt) * factor,
                                   outcome.minimum_dt,
                                   outcome.nominal_dt);
    detail_log << "  step control: " << outcome.newton_iterations << " Newton iterations, "
               << outcome.status_changes << " contact status changes, " << outcome.cutbacks
               << " cutbacks: next dt = " << next << std::endl;
    return next;
  }
} // namespace ausroll::solver

AUSROLL_REGISTER_STEP_CONTROL(
    ausroll::solver::AdaptiveParameters,
    "adaptive",
    "Adaptive",
    "as halving, and the size of the next step follows the last converged step: it shrinks by "
    "Adaptive/Target Newton iterations / iterations (or Target status changes / contact status "
    "changes) when the step needed more, grows by Step growth factor only after an easy step (at "
    "most half of both targets) and stays otherwise; after a cutback it does not grow")
