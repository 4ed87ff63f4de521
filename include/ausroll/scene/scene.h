/**
 * @file scene.h
 * A simulation scene: owns mesh, finite element, material points, loads, solvers and output, and
 * runs the load-step loop.
 */
#pragma once

#include <ausroll/adaptivity/material_point_transfer.h>
#include <ausroll/contact/contact_operator.h>
#include <ausroll/contact/curved_die_tangent.h>
#include <ausroll/contact/non_candidate_penetration.h>
#include <ausroll/io/history.h>
#include <ausroll/io/postprocess/interface.h>
#include <ausroll/material/constitutive_model.h>
#include <ausroll/mechanics/assembler.h>
#include <ausroll/mechanics/boundary_conditions.h>
#include <ausroll/mechanics/planar_kinematics.h>
#include <ausroll/scene/scene_parameters.h>
#include <ausroll/solver/linear_solver.h>
#include <ausroll/solver/newton_solver.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>
#include <string>
#include <vector>

namespace ausroll::scene
{
  /**
   * One run of ausroll. The constructor builds everything from the parameters; run() performs the
   * load steps: for each step the Newton solver iterates on this object (it implements
   * solver::NonlinearProblem), failing steps are cut back, converged steps are committed, written
   * to history.csv and (every `Output/Interval` steps) to VTU.
   */
  template <int dim>
  class Scene : public solver::NonlinearProblem
  {
  public:
    /** Build the scene described by @p parameters on communicator @p comm. */
    Scene(const SceneParameters &parameters, const MPI_Comm comm, const bool resume = false);

    /**
     * Run all load steps. Throws RunFailure (after writing the last converged state) when a step
     * does not converge within `Loading/Maximum cutbacks`.
     */
    void run();

    /** @name solver::NonlinearProblem */
    //@{
    bool   assemble(const bool with_matrix, std::string &message) override;
    double residual_norm() const override;
    /** The contact strategy's update of the statuses at a converged state (nested active set). */
    unsigned int update_constraints_at_convergence(dealii::ConditionalOStream &log) override;
    /** As the contact strategy says (nested active set: curved dies leave second-order gaps). */
    bool                    backtrack_with_small_constraint_gaps() const override;
    double                  reference_force() const override;
    double                  constraint_violation() const override;
    solver::LinearSolveInfo solve_for_increment() override;
    void                    apply_increment(const double step_length) override;
    double                  length_scale() const override;
    double                  increment_residual_product() const override;
    //@}

  private:
    /** Distribute DoFs, build constraints, sparsity, vectors and material points. */
    void setup_system();
    /** Hanging-node + Dirichlet increment constraints at the current iterate. */
    void build_newton_constraints();
    /** Accept the converged step: commit material points, remember the solution. */
    void commit_step();
    /** The read-only view of the current state for the postprocessors (Newton statistics of
        @p result and @p cutbacks, if given). */
    io::PostprocessInput<dim> postprocess_input(const solver::NewtonResult *result = nullptr,
                                                const unsigned int          cutbacks = 0) const;
    /** Quantities of the converged state for history.csv (the postprocessors' columns). */
    io::HistoryRow history_row(const solver::NewtonResult &result,
                               const unsigned int          cutbacks) const;
    /**
     * Solve the load step from the committed state to time t_start + dt: Newton with cutbacks and,
     * with the load-increment-ratio contact strategy, sub-steps that end at contact status changes.
     * Returns the time reached (dt may shrink); throws RunFailure after too many cutbacks.
     */
    double solve_step(const double          t_start,
                      double                dt,
                      solver::NewtonResult &result,
                      unsigned int         &cutbacks);
    /** After a converged step: warn (or stop, `Loading/Stop at distorted mesh`) the first time
        the volume change at a quadrature point crosses `Loading/Volume change limit`. */
    void check_distortion();
    /** Output of the current (converged) state: every postprocessor's files and the VTU. */
    void write_output();
    /**
     * Adapt the mesh by the indicators of `Adaptivity` (contact band: die positions at the current
     * time and at @p next_time), transfer solution, material points and contact statuses, and
     * re-equilibrate. Returns false if no cell was flagged.
     */
    bool adapt_mesh(const double next_time);
    /** After a mesh transfer: make the material points consistent with the interpolated
        displacement while keeping their stresses (ConstitutiveModel::rebase). */
    void rebase_material_points();
    /** Write a checkpoint of the converged state (`Checkpoint/Interval`); @p dt: next step size. */
    void write_checkpoint(const double dt);
    /** Restore time, statuses, output records and history from the checkpoint being resumed;
        returns the step size to continue with. */
    double restore_checkpoint_state();
    /** Build the postprocessors (first call) and initialize them on the current mesh (monitor
        points, reaction DoFs, probes). */
    void setup_postprocessing();
    /** Checks of a new run before anything is written: every boundary-id entry against the mesh,
        an axisymmetric body off the axis, loads finite and dies plausible at sampled times. */
    void check_setup();

    SceneParameters parameters; ///< the input
    MPI_Comm        comm;       ///< communicator
    bool            resuming;   ///< started with --resume: state from the latest checkpoint
    std::string     checkpoint_directory; ///< checkpoint read when resuming
    unsigned int    rank;                 ///< this process

    dealii::ConditionalOStream log;            ///< status lines (Verbosity normal/verbose)
    dealii::ConditionalOStream newton_log;     ///< Newton iterations (Verbosity verbose)
    dealii::ConditionalOStream regression_log; ///< deterministic lines (Verbosity regression)
    std::unique_ptr<dealii::TimerOutput>
        timer; ///< wall-time summary (reset early after a setup error)

    dealii::parallel::distributed::Triangulation<dim> triangulation;
    dealii::FESystem<dim>                             fe;
    dealii::MappingQ<dim>                             mapping;
    dealii::DoFHandler<dim>                           dof_handler;
    dealii::IndexSet                                  owned_dofs;
    dealii::IndexSet                                  relevant_dofs;

    dealii::AffineConstraints<double> hanging_constraints; ///< hanging nodes only
    dealii::AffineConstraints<double> newton_constraints;  ///< + Dirichlet increments

    dealii::TrilinosWrappers::SparseMatrix system_matrix;
    dealii::TrilinosWrappers::MPI::Vector  solution;         ///< current iterate (owned)
    dealii::TrilinosWrappers::MPI::Vector  solution_ghosted; ///< current iterate (relevant)
    dealii::TrilinosWrappers::MPI::Vector  step_start;       ///< last converged solution
    dealii::TrilinosWrappers::MPI::Vector  previous_start;   ///< the converged solution before it
    dealii::TrilinosWrappers::MPI::Vector  newton_start;     ///< iterate at the last linear solve
    dealii::TrilinosWrappers::MPI::Vector  increment;        ///< Newton increment
    dealii::TrilinosWrappers::MPI::Vector  rhs;              ///< Newton right-hand side
    dealii::TrilinosWrappers::MPI::Vector  residual;         ///< f_int - f_ext (reactions)
    dealii::TrilinosWrappers::MPI::Vector  free_residual;    ///< condensed out-of-balance force
    dealii::TrilinosWrappers::MPI::Vector  external_force;   ///< surface loads
    dealii::TrilinosWrappers::MPI::Vector  residual_ghosted; ///< residual with ghost entries

    mechanics::MaterialPointStorage<dim>                    material_points;
    std::unique_ptr<adaptivity::MaterialPointTransfer<dim>> point_transfer;

    mechanics::PlanarKinematics<dim>             kinematics;
    std::unique_ptr<material::ConstitutiveModel> model;
    mechanics::BoundaryConditions<dim>           boundary_conditions;
    std::unique_ptr<mechanics::Assembler<dim>>   assembler;
    contact::ContactOperator<dim>                contact;
    /** Curvature part of the slip-node tangent on curved dies (`Contact/Curvature tangent`). */
    contact::CurvedDieTangent<dim> curved_die_tangent;
    /** Warns once when a boundary that is not a contact candidate passes through a die. */
    contact::NonCandidatePenetration<dim> non_candidate_penetration;
    /** `Contact/Strategy`: when contact statuses change (acts on contact). */
    std::unique_ptr<contact::StatusStrategy> contact_strategy;
    /** Declared after system_matrix: destroyed first (its kept direct factorisation refers to
        the matrix). */
    solver::LinearSolver<dim> linear_solver;
    solver::NewtonSolver      newton;

    double time = 0.;           ///< pseudo-time of the current iterate
    double last_step_size = 0.; ///< size of the last converged step (predictor)
    /** First crossing of `Loading/Volume change limit` (where, when), empty while none. */
    std::string  distortion_warning;
    unsigned int step_number = 0; ///< converged steps so far
    unsigned int output_counter = 0;
    int          last_output_step = -1;

    double last_residual_norm = 0.;
    double last_reference_force = 0.;
    double largest_reference_force = 0.; ///< largest force level of the converged steps so far
    double last_constraint_violation = 0.;
    double min_cell_diameter = 1.;

    /** History columns, CSV files and VTU fields, in their fixed order (setup_postprocessing). */
    std::unique_ptr<io::PostprocessorSet<dim>> postprocessors;
    std::unique_ptr<io::History>               history; ///< history.csv (rows: postprocessors)

    dealii::Timer wall_clock;
  };

  /** Read @p parameter_file and run the scene on @p comm (dispatch on the dimension). */
  void run_scene(const std::string                    &parameter_file,
                 const MPI_Comm                        comm,
                 const bool                            resume = false,
                 const std::vector<ParameterOverride> &overrides = {});
} // namespace ausroll::scene
