/**
 * @file scene.h
 * A simulation scene: builds the parts of a run from the parameters (MechanicalSystem, Assembler,
 * ConstitutiveModel, ContactOperator with its ContactStrategy, LoadStepper, NewtonSolver,
 * postprocessors) and orchestrates them.
 */
#pragma once

#include <ausroll/adaptivity/material_point_transfer.h>
#include <ausroll/contact/contact_operator.h>
#include <ausroll/contact/contact_strategy.h>
#include <ausroll/contact/die_touch.h>
#include <ausroll/contact/non_candidate_penetration.h>
#include <ausroll/io/history.h>
#include <ausroll/io/postprocess/interface.h>
#include <ausroll/io/run_log.h>
#include <ausroll/material/constitutive_model.h>
#include <ausroll/mechanics/assembler.h>
#include <ausroll/mechanics/boundary_conditions.h>
#include <ausroll/mechanics/distortion_check.h>
#include <ausroll/mechanics/mechanical_system.h>
#include <ausroll/mechanics/planar_kinematics.h>
#include <ausroll/scene/scene_parameters.h>
#include <ausroll/solver/equilibrium_problem.h>
#include <ausroll/solver/linear_solver.h>
#include <ausroll/solver/load_stepper.h>
#include <ausroll/solver/newton_solver.h>
#include <ausroll/thermal/thermal_system.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <memory>
#include <string>
#include <vector>

namespace ausroll::scene
{
  /**
   * One run of ausroll. The constructor builds everything from the parameters; run() hands the
   * load steps to the LoadStepper, which drives this object through solver::SteppedProblem
   * (solve, restart, accept a step); the Newton solver iterates on its solver::EquilibriumProblem
   * (assemble, solve for the increment). Converged steps are committed,
   * written to history.csv and (every `Output/Interval` steps) to VTU.
   */
  template <int dim>
  class Scene : public solver::SteppedProblem
  {
  public:
    /**
     * Build the scene described by @p parameters on communicator @p comm (from the latest
     * checkpoint if @p resume). With @p check_only (`--check-input`) everything is built and
     * checked but the output directory is neither created nor written.
     */
    Scene(const SceneParameters &parameters,
          const MPI_Comm         comm,
          const bool             resume = false,
          const bool             check_only = false);

    /**
     * `--check-input`: print the sizes of the discretisation (cells, DoFs, quadrature points,
     * matrix entries, estimated memory, nominal load steps) to @p out (rank 0), and the cost of
     * one Newton iteration measured here (one assembly of residual and tangent and one linear
     * solve at the first nominal step, nothing committed) with the estimate per load step it
     * gives. Defined in check_input.cc.
     */
    void print_sizes(std::ostream &out);

    /**
     * Run all load steps. Throws RunFailure (after writing the last converged state) when a step
     * does not converge within `Loading/Maximum cutbacks`.
     */
    void run();

    /** @name solver::SteppedProblem */
    //@{
    void begin_step(const double t_start) override
    {
      time = t_start;
      step_start_time = t_start;
      contact_strategy->begin_step(system.solution_ghosted, t_start);
    }
    solver::NewtonResult solve(const double t, const double predictor_ratio) override
    {
      time = t;
      model->set_step_length(t - step_start_time); // kinetics of the material (bainite)
      system.start_step(predictor_ratio);
      thermal_current = false;
      const solver::NewtonResult result = newton.solve(*equilibrium, newton_log);
      return thermal ? iterate_coupling(result) : result;
    }
    void restart_step() override
    {
      contact_strategy->restart_step();
      if (thermal)
        restore_temperature();
    }
    unsigned int release_after_failure() override
    {
      return contact_strategy->release_after_failure();
    }
    contact::StepDecision end_of_step(const double dt) override;
    std::string           keep_last_converged(const double t_start) override;
    unsigned int          accept_step(const solver::LoadStep &step) override;
    //@}

  private:
    /** After every MechanicalSystem::setup_system(): what depends on the DoFs above
        mechanics/ (the linear solver's rigid-body modes, the contact nodes). */
    void setup_dof_dependents();
    /** Accept the converged state: commit material points, solution and contact statuses
        (@p new_step: see MechanicalSystem::commit_step). */
    void commit_step(const bool new_step = true);
    /** The read-only view of the current state for the postprocessors (Newton statistics of
        @p result and @p cutbacks, if given). */
    io::PostprocessInput<dim> postprocess_input(const solver::NewtonResult *result = nullptr,
                                                const unsigned int          cutbacks = 0) const;
    /** After a converged step: warn (or stop, `Loading/Stop at distorted mesh`) the first time
        the volume change at a quadrature point crosses `Loading/Volume change limit`. */
    void check_distortion();
    /** After a converged solve (2D, `Contact/Penetrating boundaries = add`): if a boundary that
        is not a candidate of a die lies inside it, make it a candidate, say so and return true
        (the step is then solved again from its start). */
    bool add_penetrating_boundaries();
    /** Output of the current (converged) state: every postprocessor's files and the VTU. */
    void write_output();
    /**
     * Adapt the mesh by the indicators of `Adaptivity` (contact band: die positions at the current
     * time and at @p next_time), transfer solution, material points and contact statuses, and
     * re-equilibrate. Returns false if no cell was flagged.
     */
    bool adapt_mesh(const double next_time);
    /** Write a checkpoint of the converged state (`Checkpoint/Interval`); @p dt: next step size. */
    void write_checkpoint(const double dt);
    /** Restore time, statuses, output records and history from the checkpoint being resumed;
        returns the step size to continue with. */
    double restore_checkpoint_state();
    /** Build the postprocessors (first call) and initialize them on the current mesh (monitor
        points, reaction DoFs, probes). */
    void setup_postprocessing();
    /** @name The temperature field (`Thermal/Enabled`; scene/coupling.cc) */
    //@{
    /** Build the temperature field on the mechanical mesh and quadrature (after
        MechanicalSystem::setup_system()). */
    void setup_thermal();
    /** Temperature at t = 0 on the field and the material points (not when resuming). */
    void initialize_temperature();
    /** `Phases/Carbon content` at the material points (material::CarbonProfile, its depth below
        `Phases/Case boundaries`, by default the dies' Candidate boundaries; InputError outside 0
        to 2.1 wt%), the initial temperature, and the phases at t = 0 from both
        (material::initialize_phase_state(): `Phases/Initial state`); at set-up (before anything
        is written) and again after the initial refinement cycles (not when resuming: the
        checkpoint holds them). */
    void initialize_phases();
    /** Isothermal split, thermal half: the heat equation over the converged mechanical @p step
        (before the material points are committed), then the new temperature at the points. */
    void thermal_step(const solver::LoadStep &step);
    /** `Coupling/Iterations` > 1: after the mechanical solve @p result, heat solve and mechanics
        at the new temperature in turn until the temperature settles; returns the Newton
        statistics of all mechanical solves of the step. */
    solver::NewtonResult iterate_coupling(const solver::NewtonResult &result);
    /** After a failed attempt: the temperature of the step's start on the field and at the
        material points (the repeated split may have changed them). */
    void restore_temperature();
    //@}

    SceneParameters parameters; ///< the input
    MPI_Comm        comm;       ///< communicator
    bool            resuming;   ///< started with --resume: state from the latest checkpoint
    bool            checking;   ///< built by --check-input: nothing is written
    std::string     checkpoint_directory; ///< checkpoint read when resuming
    unsigned int    rank;                 ///< this process

    dealii::ConditionalOStream log;            ///< status lines (Verbosity normal/verbose)
    dealii::ConditionalOStream newton_log;     ///< Newton iterations (Verbosity verbose)
    dealii::ConditionalOStream regression_log; ///< deterministic lines (Verbosity regression)
    std::unique_ptr<dealii::TimerOutput>
        timer; ///< wall-time summary (reset early after a setup error)

    /** Mesh, FE, DoFs, constraints, matrix, vectors, material points. */
    mechanics::MechanicalSystem<dim>                        system;
    std::unique_ptr<adaptivity::MaterialPointTransfer<dim>> point_transfer;

    mechanics::PlanarKinematics<dim>             kinematics;
    std::unique_ptr<material::ConstitutiveModel> model;
    mechanics::BoundaryConditions<dim>           boundary_conditions;
    std::unique_ptr<mechanics::Assembler<dim>>   assembler;
    contact::ContactOperator<dim>                contact;
    /** The temperature field of a thermal scene (null: isothermal). */
    std::unique_ptr<thermal::ThermalSystem<dim>> thermal;
    /** The last heat solve belongs to the current mechanical solution (repeated split). */
    bool thermal_current = false;
    /** Warns once when a boundary that is not a contact candidate passes through a die. */
    contact::NonCandidatePenetration<dim> non_candidate_penetration;
    /** Pseudo-time at the start of the current load step. */
    double step_start_time = 0.;
    /** `Contact/Strategy`: when contact statuses change (acts on contact). */
    std::unique_ptr<contact::StatusStrategy> contact_strategy;
    /** Declared after the system (its matrix): destroyed first (its kept direct factorisation
        refers to the matrix). */
    solver::LinearSolver<dim> linear_solver;
    solver::NewtonSolver      newton;
    solver::LoadStepper       stepper; ///< steps, cutbacks, step-size control, predictor
    /** What Newton iterates on: equilibrium of the system at `time` with contact. */
    std::unique_ptr<solver::EquilibriumProblem<dim>> equilibrium;
    /** First crossing of `Loading/Volume change limit` (where, when). */
    mechanics::DistortionMonitor<dim> distortion;

    double       time = 0.;       ///< pseudo-time of the current iterate
    unsigned int step_number = 0; ///< converged steps so far
    unsigned int output_counter = 0;
    int          last_output_step = -1;

    double start_fraction = 0.;               ///< fraction of the run done before this process
    double smallest_extent = 0.;              ///< of the workpiece (small-strain warning)
    bool   large_displacement_warned = false; ///< the small-strain warning was given
    /** Per die: a node was closed on it at the end of some step of this process (a run that
        ends with a die never touched stops with a message; not checked after --resume). */
    contact::DieTouchRecord die_touches;
    io::RunTotals    run_totals; ///< cutbacks, peak die forces, CPU at the start (the summary)
    io::EtaEstimator eta;        ///< the ETA of the step lines

    /** History columns, CSV files and VTU fields, in their fixed order (setup_postprocessing). */
    std::unique_ptr<io::PostprocessorSet<dim>> postprocessors;
    std::unique_ptr<io::History>               history; ///< history.csv (rows: postprocessors)

    dealii::Timer wall_clock;
  };

  /**
   * Read @p parameter_file and run the scene on @p comm (dispatch on the dimension). With
   * @p check_only (`--check-input`): build the scene, run the set-up checks, print its sizes
   * (Scene::print_sizes()) and return without writing anything.
   */
  void run_scene(const std::string                    &parameter_file,
                 const MPI_Comm                        comm,
                 const bool                            resume = false,
                 const std::vector<ParameterOverride> &overrides = {},
                 const bool                            check_only = false);
} // namespace ausroll::scene
