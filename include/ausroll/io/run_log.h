/**
 * @file run_log.h
 * The lines a run prints on the terminal (`Output/Verbosity`): the header, one line per
 * converged step, the deterministic regression lines and the closing line.
 */
#pragma once

#include <ausroll/io/history.h>
#include <ausroll/io/output_parameters.h>
#include <ausroll/solver/load_stepper.h>
#include <ausroll/solver/newton_solver.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/types.h>

#include <mpi.h>

#include <initializer_list>
#include <string>
#include <vector>

namespace ausroll::contact
{
  template <int dim>
  class ContactOperator;
} // namespace ausroll::contact

namespace ausroll::io
{
  /** Whether rank @p rank prints at verbosity @p v a stream meant for the verbosities @p set
      (only rank 0 prints). */
  bool prints(const Verbosity v, std::initializer_list<Verbosity> set, const unsigned int rank);

  /** "12.3 s" (one decimal below 10 s). */
  std::string format_seconds(const double s);

  /**
   * The header of a run: "ausroll: NAME  (N MPI ranks)", mesh, @p element, @p kinematics and the
   * output directory on @p log; "scene: NAME" with cells and DoFs on @p regression_log.
   */
  void write_run_header(dealii::ConditionalOStream &log,
                        dealii::ConditionalOStream &regression_log,
                        const std::string          &name,
                        const unsigned int          n_ranks,
                        const unsigned long long    n_cells,
                        const unsigned long long    n_dofs,
                        const std::string          &element,
                        const std::string          &kinematics,
                        const std::string          &directory);

  /** "finished: N steps in T; history: DIR/history.csv[, ParaView: DIR/solution.pvd]". */
  void write_run_footer(dealii::ConditionalOStream &log,
                        const unsigned int          steps,
                        const double                seconds,
                        const std::string          &directory,
                        const bool                  with_vtu);

  /**
   * "Newton: S solves in N steps (median M per step)[, D more in discarded attempts (failed and
   * solved again, or shortened)]": the whole Newton cost of the run. @p solves are those of the
   * accepted attempts of the @p steps steps, @p discarded those of the other attempts.
   */
  void write_solve_summary(dealii::ConditionalOStream &log,
                           const std::size_t           steps,
                           const unsigned long long    solves,
                           const double                median,
                           const unsigned long long    discarded);

  /** What the line of a converged step reports. */
  struct StepSummary
  {
    unsigned int         step = 0;            ///< converged steps
    double               time = 0.;           ///< pseudo-time reached
    double               fraction = 0.;       ///< share of the run done (StageParameters::progress)
    double               start_fraction = 0.; ///< fraction done before this process started
    solver::NewtonResult result;              ///< Newton statistics of the step
    unsigned int         cutbacks = 0;        ///< cutbacks of the step
    bool                 contact = false;     ///< the run has dies (stick/slip counts)
    unsigned int         n_stick = 0, n_slip = 0; ///< sticking / slipping contact nodes
    dealii::types::global_dof_index n_dofs = 0;   ///< DoFs
    double                          elapsed = 0.; ///< wall seconds since the start
  };

  /**
   * "step N  t = ...  (..%)  Newton k  cutbacks c  stick/slip a/b  DoFs n  elapsed  ETA". The ETA
   * is @p eta (seconds; EtaEstimator).
   */
  void write_step_line(dealii::ConditionalOStream &log, const StepSummary &s, const double eta);

  /**
   * The remaining wall time of a run from the progress so far. The cost of a unit of load
   * parameter is measured twice: over the whole run so far (this process) and over its recent
   * part (the steps covering the last third of the load done, at least the last 3 steps); the
   * larger rate times the load parameter still to go is the ETA. A run whose steps grow dearer
   * (the contact zone grows, the mesh is refined near the die, more Newton iterations) is then
   * not promised the cheap start's pace.
   */
  class EtaEstimator
  {
  public:
    /** Start of the run: load fraction @p start_fraction done at wall time @p elapsed. */
    void start(const double start_fraction, const double elapsed);
    /** A converged step: load fraction @p fraction done at wall time @p elapsed (seconds). */
    void add(const double fraction, const double elapsed);
    /** Estimated wall seconds to load fraction 1. */
    double eta() const;

  private:
    std::vector<std::pair<double, double>> progress; ///< (fraction, elapsed), first the start
  };

  /** What the closing summary of a run adds up (for the steps of this process). */
  struct RunTotals
  {
    unsigned int             cutbacks = 0; ///< cutbacks of the accepted steps
    std::vector<std::string> die_names;    ///< `Contact/Die N/Name`
    std::vector<double>      peak_force;   ///< per die: max |force| over the converged steps
    std::vector<double>      peak_time;    ///< per die: pseudo-time of that peak

    /** Record the force magnitude @p force of die @p k (@p name) at pseudo-time @p time. */
    void record_force(const unsigned int k,
                      const std::string &name,
                      const double       force,
                      const double       time);

    /** record_force() of every die of @p contact at pseudo-time @p time (collective). */
    template <int dim>
    void record_die_forces(const contact::ContactOperator<dim> &contact, double time);
  };

  /** CPU seconds (user + system) used so far by this process (getrusage). */
  double process_cpu_seconds();

  /**
   * The closing summary (`Output/Verbosity` quiet, normal, verbose) on @p log:
   * "Newton: S solves in N steps (median M per step)[, D more in discarded attempts ...]", then
   * "steps: N converged, C cutbacks", "peak die force: NAME |F|max = ... N at t = ..." per die,
   * "time: W s wall, C s CPU (all ranks)" (CPU since the processes started, summed over
   * @p comm; collective).
   */
  void write_run_summary(dealii::ConditionalOStream &log,
                         const RunTotals            &totals,
                         const std::size_t           steps,
                         const unsigned long long    solves,
                         const double                median,
                         const unsigned long long    discarded,
                         const double                wall_seconds,
                         const MPI_Comm              comm);

  /**
   * The end of a run of @p steps steps after @p wall_seconds: write_run_summary(), the line
   * "assemblies: T: F at the start of a solve (s CPU), A after a linear solve (s CPU), L
   * line-search trials (s CPU), P after status changes (s CPU); R of all re-used the cell
   * matrices of the same state" of @p solve_count (if it counted any; the counts and CPU seconds
   * of rank 0), write_run_footer() (`Output/Verbosity` quiet, normal,
   * verbose; rank @p rank), the timer table of @p timer (normal, verbose), "finished: N steps" on
   * @p regression_log. Collective.
   */
  void write_run_end(const OutputParameters     &output,
                     const unsigned int          rank,
                     const RunTotals            &totals,
                     const solver::SolveCount   &solve_count,
                     const unsigned int          steps,
                     const double                wall_seconds,
                     dealii::TimerOutput        &timer,
                     dealii::ConditionalOStream &regression_log,
                     const MPI_Comm              comm);

  /** "step N name=value ..." with 5 digits (wall_seconds and step left out, |x| < 1e-12: 0). */
  void write_regression_line(dealii::ConditionalOStream &log,
                             const unsigned int          step,
                             const HistoryRow           &row);

  /**
   * The small-strain warning on std::cerr (rank 0) when the largest displacement @p max_u of
   * step @p step exceeds 10 % of the workpiece's smallest extent @p extent; returns whether it
   * was given.
   */
  bool warn_large_displacement(const unsigned int step,
                               const double       max_u,
                               const double       extent,
                               const unsigned int rank);
} // namespace ausroll::io
