/**
 * @file stage_parameters.h
 * The `Stages` subsection: a process chain in one run (quench into the bath, rolling, die
 * withdrawn, cooling to room temperature), as consecutive time intervals with their own thermal
 * boundary conditions and step size. The die motions stay functions of t (`Contact/Die N/
 * Motion`); a stage switches boundary conditions and step sizes, and its end is a load-step
 * boundary the stepper lands on exactly.
 */
#pragma once

#include <ausroll/thermal/thermal_parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace ausroll::solver
{
  struct LoadingParameters;

  /**
   * One stage (`Stages/Stage k`): the time interval (end time of the stage before, `End time`],
   * like an Abaqus *STEP or a DEFORM operation, but on the run's one clock t.
   */
  struct Stage
  {
    std::string name;      ///< `Name` (default "stage k")
    double      end_time;  ///< `End time`
    double      step_size; ///< `Step size` (0: Loading's End time / Number of steps)
    /** The `Thermal/Condition k` list in force during the stage: the Thermal conditions with
        this stage's `Thermal condition values` and `Heat transfer coefficients` applied. */
    std::vector<thermal::ThermalCondition> thermal_conditions;
  };

  /**
   * Parameters of subsection `Stages`. Without stages (`Number of stages = 0`) a run is exactly
   * what it was before stages existed. With stages they tile [0, Loading/End time]: their end
   * times increase and the last one equals Loading/End time (a stage may not overlap the one
   * before it, and the run has no time outside a stage).
   */
  struct StageParameters
  {
    static constexpr unsigned int max_stages = 8; ///< declared `Stage 0..7`
    std::vector<Stage>            stages;         ///< `Stage 0..Number of stages - 1`

    /** Whether stages are declared (`Number of stages` > 0). */
    bool declared() const { return !stages.empty(); }

    /** Start time of stage @p k (0 or the end time of stage k - 1). */
    double start_time(const unsigned int k) const;

    /**
     * The stage a step starting at @p t_start belongs to: the first whose end lies after it
     * (by more than 1e-10 of the last end time, so that a step starting where a stage ended
     * to round-off belongs to the next stage).
     */
    unsigned int stage_at(const double t_start) const;

    /** Whether @p t is the end time of a stage (to 1e-10 of the last end time). */
    bool ends_stage(const double t) const;

    /** Nominal step size of stage @p k: its `Step size` or @p loading_step. */
    double step_size(const unsigned int k, const double loading_step) const;

    /**
     * The share of the run done at time @p t, counted in nominal steps (each stage's duration
     * over its step size), so that a long cooling stage of few steps does not look like most of
     * the run (the run log's percentage and time estimate); without stages t / End time of
     * @p loading.
     */
    double progress(const double t, const LoadingParameters &loading) const;

    /**
     * At most about @p max_samples times from 0 to the End time of @p loading (both included) at
     * which the set-up checks evaluate loads and die positions: evenly spaced without stages;
     * with stages spread over the stages by their nominal steps, at least the stage's ends and
     * one time inside each, so that a short stage of many steps (the feed of a die) is not
     * skipped by a long one of few steps (the cooling).
     */
    std::vector<double> sample_times(const LoadingParameters &loading,
                                     const unsigned int       max_samples) const;

    static void declare_parameters(dealii::ParameterHandler &prm);

    /**
     * Read the subsection. The stages' ends are checked against @p loading (`End time`), their
     * thermal overrides against @p thermal (the conditions they name must exist; a heat
     * transfer coefficient only for a convection). Throws InputError naming the entry.
     */
    void parse_parameters(dealii::ParameterHandler         &prm,
                          const LoadingParameters          &loading,
                          const thermal::ThermalParameters &thermal);
  };
} // namespace ausroll::solver
