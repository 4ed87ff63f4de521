/**
 * @file loading_parameters.h
 * The `Loading` subsection: load (pseudo-time) stepping and automatic cutback.
 */
#pragma once

#include <deal.II/base/parameter_handler.h>

namespace ausroll::solver
{
  /** Initial guess of the Newton iteration of a load step (`Loading/Predictor`). */
  enum class Predictor
  {
    none,                ///< start from the last converged state
    linear_extrapolation ///< u_n + (dt / dt_prev) (u_n - u_n-1): follows the path of the last step
  };

  /** How the load stepper chooses the next step size (`Loading/Step control`). */
  enum class StepControl
  {
    halving, ///< halve after a failure; grow by the growth factor after every step without one
    adaptive ///< also from the Newton iterations and contact status changes of the last step
  };

  /**
   * Parameters of subsection `Loading`. Loads and prescribed motions are functions of the
   * pseudo-time t in [0, End time]; the load factor reported in the history is t / End time.
   */
  struct LoadingParameters
  {
    /**
     * Factor for the size of the step after a converged step that took @p newton_iterations
     * Newton iterations and changed @p status_changes contact statuses (`Step control =
     * adaptive`): shrink by target / actual (not below `Minimum step factor`) when either
     * exceeds its target, grow by `Step growth factor` when the step was easy (at most half the
     * target iterations and half the target status changes), keep the size otherwise.
     */
    double step_factor(const unsigned int newton_iterations,
                       const unsigned int status_changes) const;

    static constexpr int max_steps = 1000000; ///< upper bound of `Number of steps`
    double               end_time = 1.;       ///< `End time`
    unsigned int number_of_steps = 10;     ///< `Number of steps` (nominal step = End time / steps)
    unsigned int max_cutbacks = 6;         ///< `Maximum cutbacks` per step (each halves the step)
    double       step_growth_factor = 1.5; ///< `Step growth factor` back towards the nominal step
    Predictor    predictor = Predictor::none;         ///< `Predictor` of the first Newton iterate
    StepControl  step_control = StepControl::halving; ///< `Step control`
    unsigned int target_newton_iterations = 4;        ///< `Target Newton iterations` (adaptive)
    unsigned int target_status_changes = 4;    ///< `Target status changes` (adaptive; 0: off)
    double       minimum_step_factor = 0.25;   ///< `Minimum step factor`: smallest shrink per step
    double       minimum_step_fraction = 1e-4; ///< `Minimum step fraction` of the nominal step
    double       volume_change_limit = 0.2;    ///< `Volume change limit`: J outside [l, 1/l] folds
    bool         stop_at_distortion = false;   ///< `Stop at distorted mesh`

    /** Declare subsection `Loading`. */
    static void declare_parameters(dealii::ParameterHandler &prm);
    /** Read subsection `Loading`. */
    void parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace ausroll::solver
