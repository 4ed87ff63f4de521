/**
 * @file loading_parameters.h
 * The `Loading` subsection: load (pseudo-time) stepping and automatic cutback.
 */
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <map>
#include <memory>
#include <string>

namespace ausroll::solver
{
  /** Initial guess of the Newton iteration of a load step (`Loading/Predictor`). */
  enum class Predictor
  {
    none,                ///< start from the last converged state
    linear_extrapolation ///< u_n + (dt / dt_prev) (u_n - u_n-1): follows the path of the last step
  };

  class StepControlParameters;

  /**
   * Parameters of subsection `Loading`. Loads and prescribed motions are functions of the
   * pseudo-time t in [0, End time]; the load factor reported in the history is t / End time.
   */
  struct LoadingParameters
  {
    static constexpr int max_steps = 1000000; ///< upper bound of `Number of steps`
    double               end_time = 1.;       ///< `End time`
    unsigned int number_of_steps = 10;     ///< `Number of steps` (nominal step = End time / steps)
    unsigned int max_cutbacks = 6;         ///< `Maximum cutbacks` per step (each halves the step)
    double       step_growth_factor = 1.5; ///< `Step growth factor` back towards the nominal step
    Predictor    predictor = Predictor::none; ///< `Predictor` of the first Newton iterate
    /** `Step control`: the name of a registered step control (solver/step_control.h). */
    std::string step_control = "halving";
    /** The entries of the step control's own subsection `Loading/<Step control>` (`Adaptive`);
        set by parse_parameters(); null: the registered defaults of `step_control`. */
    std::shared_ptr<const StepControlParameters> step_control_parameters;
    double minimum_step_fraction = 1e-4; ///< `Minimum step fraction` of the nominal step
    double volume_change_limit = 0.2;    ///< `Volume change limit`: J outside [l, 1/l] folds
    bool   stop_at_distortion = false;   ///< `Stop at distorted mesh`

    /** Declare subsection `Loading`. */
    static void declare_parameters(dealii::ParameterHandler &prm);
    /** The entries an old `.prm` file may still set and where they are now (old full path ->
        new full path): the adaptive step control's entries moved into `Loading/Adaptive`. */
    static std::map<std::string, std::string> moved_entries();
    /** Read subsection `Loading`. */
    void parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace ausroll::solver
