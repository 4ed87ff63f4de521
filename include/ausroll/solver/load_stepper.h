/**
 * @file load_stepper.h
 * The load-step loop: pseudo-time steps on the grid of nominal steps, cutbacks, the step-size
 * control of `Loading/Step control`, the linear-extrapolation predictor with its retry, and the
 * contact strategy's decision at the end of a step. It drives the scene through the small
 * SteppedProblem interface, so that it can be tested on a model problem without a mesh
 * (tests/unit/test_load_stepper.cc).
 */
#pragma once

#include <ausroll/contact/contact_strategy.h>
#include <ausroll/solver/loading_parameters.h>
#include <ausroll/solver/newton_solver.h>
#include <ausroll/solver/stage_parameters.h>
#include <ausroll/solver/step_control.h>

#include <deal.II/base/conditional_ostream.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace ausroll::solver
{
  /** A converged load step as the load stepper hands it to SteppedProblem::accept_step(). */
  struct LoadStep
  {
    unsigned int number = 0;   ///< its number (1 for the first step of the run)
    double       t_start = 0.; ///< pseudo-time at its start
    double       time = 0.;    ///< pseudo-time reached (t_start + the size actually taken)
    /** The step size the stepper held before this step (the size it would try next without
        step control): the adaptivity's look-ahead and the size a checkpoint stores. */
    double       step_size = 0.;
    NewtonResult result;       ///< Newton statistics of the converged solve
    unsigned int cutbacks = 0; ///< cutbacks of this step
    /** Linear solves of this step's attempts that were not accepted: failed (then retried
        without the predictor, with released statuses or cut back) or converged but shortened
        by the contact strategy (`Contact/Strategy = load increment ratio`). */
    unsigned int discarded_solves = 0;
  };

  /**
   * The Newton solves of a run (since its start or its restart from a checkpoint): those of the
   * accepted attempt of every step (the `newton_iterations` of the history) and those of the
   * attempts that were discarded, so that the cost of a run is complete where a step was solved
   * more than once.
   */
  struct SolveCount
  {
    std::vector<unsigned int> per_step;      ///< solves of the accepted attempt of each step
    unsigned long long        discarded = 0; ///< solves of the discarded attempts
    /** The assemblies of all Newton solves of the run (NewtonSolver::assembly_count(); the
        owner of the solver fills it in before the summary) */
    AssemblyCount assemblies;
    /** Of these, the assemblies that re-used the cell matrices of an assembly at the same state
        (mechanics::AssemblyCache hits: a re-assembly after status changes) */
    unsigned long long reused_assemblies = 0;

    /** Sum of per_step. */
    unsigned long long accepted() const;

    /** Median of per_step (0 without steps). */
    double median() const;
  };

  /**
   * What the load stepper drives (the scene implements it). A load step, as LoadStepper calls it:
   *   begin_step(t_start)
   *   repeat:  solve(t, ratio)         from the committed state (ratio != 0: with the predictor)
   *            failed:    restart_step(), then again without the predictor (and, once, with
   *                       release_after_failure()) or with half the step
   *            converged: end_of_step(dt): accept, or solve again with dt * step_factor
   *   accept_step(step)                commit, history, output, ...
   * After too many cutbacks: keep_last_converged(t_start), then RunFailure.
   */
  class SteppedProblem
  {
  public:
    virtual ~SteppedProblem() = default;

    /** A load step begins from the committed state at @p t_start. */
    virtual void begin_step(const double t_start) = 0;

    /**
     * Solve the step to pseudo-time @p time from the committed state: the first iterate is the
     * committed solution u_n, or with @p predictor_ratio != 0 u_n + ratio (u_n - u_n-1).
     */
    virtual NewtonResult solve(const double time, const double predictor_ratio) = 0;

    /** The solve failed: the step will be solved again from the committed state. */
    virtual void restart_step() = 0;

    /**
     * After a failed solve and restart_step(): change the contact statuses for one more solve of
     * the same step (contact::StatusStrategy::release_after_failure()); returns the number of
     * changes (0: nothing to try). Default: none.
     */
    virtual unsigned int release_after_failure() { return 0; }

    /** After a converged solve of a step of size @p dt: the contact strategy's decision. */
    virtual contact::StepDecision end_of_step(const double dt) = 0;

    /**
     * The run fails: make the committed state at @p t_start the current one and write it out.
     * Returns a note appended to the failure message (an earlier warning), or "".
     */
    virtual std::string keep_last_converged(const double t_start) = 0;

    /** Accept the converged step @p step (commit, history, output, mesh adaptation, ...).
        Returns the number of contact status changes in the step (adaptive step control). */
    virtual unsigned int accept_step(const LoadStep &step) = 0;
  };

  /**
   * The load steps from a start time to `Loading/End time`. Steps end on the grid of nominal
   * steps (End time / Number of steps), also after cutbacks and shortened sub-steps, so that the
   * outputs of different runs share their times. A failed solve is first tried again without
   * the predictor (if it was used) and, once per step, with the contact statuses of
   * SteppedProblem::release_after_failure() (if it changed any), then with half the step, at most
   * `Maximum cutbacks` times and not below `Minimum step fraction` of the nominal step; then
   * RunFailure names the step, its time, the reason and where the last converged state is. The next
   * step size: `Step control = halving` keeps the size that worked after a cutback and grows by
   * `Step growth factor` (to at most the nominal step) otherwise; `adaptive` scales it by
   * AdaptiveStepControl::step_factor() of the Newton iterations and contact status changes (at most
   * 1 after a cutback); the rules are registered (solver/step_control.h).
   */
  class LoadStepper
  {
  public:
    /**
     * Stepper by @p loading; @p output_directory is named in the failure message. Cutbacks and
     * retries go to @p log, per-step details (Newton start, step control) to @p detail_log.
     */
    LoadStepper(const LoadingParameters    &loading,
                const std::string          &output_directory,
                dealii::ConditionalOStream &log,
                dealii::ConditionalOStream &detail_log);

    /** End time / Number of steps. */
    double nominal_step_size() const;

    /**
     * Step through the process stages @p stages (`Stages`, kept by reference; not called
     * without stages): steps end on each stage's end and its grid (stage_targets()), a stage
     * begins with its own step size, and the step-size control, cutbacks and the minimum step
     * act within the stage's nominal step.
     */
    void set_stages(const StageParameters *stages);

    /** `Minimum step fraction` of the nominal step: the smallest step a cutback or the
        adaptive step control gives. */
    double minimum_step_size() const;

    /**
     * Run the steps of @p problem from @p t_done (after @p steps_done converged steps) with the
     * step size @p dt to the end time. Throws RunFailure after too many cutbacks.
     */
    void run(SteppedProblem &problem, double t_done, double dt, unsigned int steps_done);

    /**
     * Solve step number @p number from @p t_start with size @p dt (cutbacks, predictor retry,
     * end-of-step decisions). Returns the converged step (its step_size is left 0).
     */
    LoadStep
    solve_step(SteppedProblem &problem, const unsigned int number, const double t_start, double dt);

    /**
     * The step size after the converged @p step of size @p dt_taken, when the stepper held
     * @p dt before it, with @p status_changes contact status changes.
     */
    double next_step_size(const double       dt,
                          const double       dt_taken,
                          const LoadStep    &step,
                          const unsigned int status_changes) const;

    /** Size of the last converged step (the predictor's u_n - u_n-1 spans it; 0: none yet). */
    double last_step_size = 0.;

    /** The solves of the steps run by run() so far. */
    SolveCount solve_count;

  private:
    /**
     * With stages: the next grid point after @p t_done and the end of the stage the step from
     * @p t_done lies in. Where the stepper enters a stage, it logs the stage (at its start:
     * "Stage k (name): t = a to b, step h", sets @p dt to the stage's step and solves the
     * stage's first step without the predictor (the last stage's increment says nothing of the
     * path under the new conditions); inside it, as
     * after a resume: "resuming in stage k (name)").
     */
    std::pair<double, double> stage_targets(const double t_done, double &dt);

    /** The nominal step of the stage the stepper is in, or End time / Number of steps. */
    double current_nominal_step() const;

    const StageParameters      *stages = nullptr;   ///< `Stages`, or none
    int                         current_stage = -1; ///< the stage of the last step (-1: none)
    double                      stage_step = 0.;    ///< its nominal step
    LoadingParameters           loading;
    std::string                 output_directory;
    dealii::ConditionalOStream &log;
    dealii::ConditionalOStream &detail_log;
    /** The rule of `Loading/Step control`. */
    std::shared_ptr<const StepControl> step_control;
  };
} // namespace ausroll::solver
