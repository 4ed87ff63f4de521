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

    /** Declare subsection `Loading`. */
    static void declare_parameters(dealii::ParameterHandler &prm);
    /** Read subsection `Loading`. */
    void parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace ausroll::solver
