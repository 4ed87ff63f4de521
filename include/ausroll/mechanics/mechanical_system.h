/**
 * @file mechanical_system.h
 * The discrete mechanical system of a scene: mesh, finite element, mapping, DoFs, constraints,
 * matrix, the displacement vectors of the load-step state and the material points, with one
 * owner.
 */
#pragma once

#include <ausroll/material/constitutive_model.h>
#include <ausroll/mechanics/assembler.h>
#include <ausroll/mechanics/boundary_conditions.h>
#include <ausroll/mechanics/material_point_storage.h>

#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <functional>
#include <utility>

namespace ausroll::mechanics
{
  /**
   * Mesh, FE_Q(degree)^dim, MappingQ(degree), DoFs with their index sets, the hanging-node and
   * Newton constraints, the tangent matrix and the vectors of the load-step state, and the
   * material points of the locally owned cells (one MaterialPoint per quadrature point).
   *
   * The step state: `solution` is the current iterate (`solution_ghosted` its copy with ghost
   * entries; every change of `solution` is followed by `solution_ghosted = solution`),
   * `step_start` the last converged solution and `previous_start` the one before it (the
   * predictor's). commit_step() accepts the iterate as converged, restore_step_start() returns to
   * the last converged state (vectors and trial material states). Generalized plane strain:
   * the out-of-plane stretch (@ref out_of_plane) follows the same steps as the displacement.
   *
   * What lies above mechanics/ (linear solver, contact nodes, material-point transfer) is set up by
   * the owner of the system after setup_system() (see scene::Scene::setup_dof_dependents()).
   * The data members are public: the system is the state the other parts read and write.
   */
  template <int dim>
  class MechanicalSystem
  {
  public:
    using Vector = dealii::TrilinosWrappers::MPI::Vector;

    /** An empty system on @p comm with elements of degree @p degree (mesh still to be made). */
    MechanicalSystem(const MPI_Comm comm, const unsigned int degree);

    /** Distribute the DoFs, build the hanging-node constraints, the sparsity pattern and the
        matrix, size all vectors (zero) and find the smallest cell diameter. */
    void setup_system();

    /** The smallest edge of the mesh's bounding box (all ranks). */
    double smallest_extent() const;

    /** Create the material points (@p points_per_cell per locally owned cell). */
    void initialize_material_points(const unsigned int points_per_cell);

    /**
     * Build the constraints of a Newton increment at the current iterate: hanging nodes, the
     * Dirichlet increments of @p boundary_conditions at @p time and, if given, what @p add_more
     * adds (contact), which returns its largest constraint violation. Returns the largest
     * violation over all ranks (|inhomogeneity| of the owned Dirichlet lines, or add_more's).
     */
    double build_newton_constraints(
        const BoundaryConditions<dim>                                    &boundary_conditions,
        const double                                                      time,
        const std::function<double(dealii::AffineConstraints<double> &)> &add_more = {});

    /**
     * The first iterate of a load step: the last converged solution, or with
     * @p predictor_ratio != 0 its linear extrapolation u_n + ratio (u_n - u_n-1).
     */
    void start_step(const double predictor_ratio);

    /** Return to the last converged state: solution = step_start, trial material states =
        committed ones. */
    void restore_step_start();

    /** Accept the current iterate as converged: commit the material points, step_start =
        solution and, for a @p new_step (not a re-equilibration on a new mesh at the same time),
        previous_start = step_start first (the predictor extrapolates from the last two steps). */
    void commit_step(const bool new_step = true);

    /** Zero residual, external_force, free_residual and, with @p with_matrix, system_matrix and
        rhs: the targets of an assembly. */
    AssemblyTargets assembly_targets(const bool with_matrix);

    /** Set the iterate to newton_start + @p step_length * increment. */
    void apply_increment(const double step_length);

    /** Norm (over all ranks) of the residual entries at the DoFs with a prescribed (Newton, not
        hanging-node) constraint: the reaction force level. */
    double reaction_norm() const;

    /**
     * Refine / coarsen the mesh as flagged, carrying the solution along: @p attach_data (e.g.
     * MaterialPointTransfer::prepare()) runs just before the mesh changes, @p unpack_data (e.g.
     * MaterialPointTransfer::unpack()) after setup_system() on the new mesh. The interpolated
     * solution (hanging nodes distributed) becomes solution and step_start. Returns the cells
     * split and the cells merged into their parents (over all ranks), counted from the flags as
     * executed (after the 2:1 balance and the whole-family rule of
     * prepare_coarsening_and_refinement()).
     */
    std::pair<unsigned int, unsigned int>
    execute_refinement(const std::function<void()> &attach_data,
                       const std::function<void()> &unpack_data);

    /** Make the material points consistent with the current displacement while keeping their
        stresses (ConstitutiveModel::rebase with the F the material sees, F-bar included). */
    void rebase_material_points(const Assembler<dim>              &assembler,
                                const material::ConstitutiveModel &model);

    MPI_Comm comm; ///< communicator

    dealii::parallel::distributed::Triangulation<dim> triangulation; ///< the workpiece mesh
    dealii::FESystem<dim>                             fe;            ///< FE_Q(degree)^dim
    dealii::MappingQ<dim>                             mapping;       ///< MappingQ(degree)
    dealii::DoFHandler<dim>                           dof_handler;   ///< displacement DoFs
    dealii::IndexSet                                  owned_dofs;    ///< locally owned DoFs
    dealii::IndexSet                                  relevant_dofs; ///< locally relevant DoFs

    dealii::AffineConstraints<double> hanging_constraints; ///< hanging nodes only
    dealii::AffineConstraints<double> newton_constraints;  ///< + Dirichlet increments (+ contact)

    dealii::TrilinosWrappers::SparseMatrix system_matrix;    ///< Newton tangent
    Vector                                 solution;         ///< current iterate (owned)
    Vector                                 solution_ghosted; ///< current iterate (relevant)
    Vector                                 step_start;       ///< last converged solution
    Vector                                 previous_start;   ///< the converged solution before it
    Vector                                 newton_start;     ///< iterate at the last linear solve
    Vector                                 increment;        ///< Newton increment
    Vector                                 rhs;              ///< Newton right-hand side
    Vector                                 residual;         ///< f_int - f_ext (reactions)
    Vector                                 free_residual;    ///< condensed out-of-balance force
    Vector                                 external_force;   ///< surface loads
    Vector                                 residual_ghosted; ///< residual with ghost entries

    MaterialPointStorage<dim> material_points; ///< states of the locally owned cells

    /** Generalized plane strain: the global out-of-plane stretch, its step state and the border
        of the Newton system (inactive for the other planar models and 3D). */
    GeneralizedPlaneStrain out_of_plane;

    double min_cell_diameter = 1.; ///< smallest vertex distance of the mesh (all ranks)

    /** The cell part of the last assembly for the next one at the same state (Assembler::
        assemble); every method here that changes the material points or the mesh increments
        its state counter. Code that changes the material points in another way must do so too. */
    AssemblyCache assembly_cache;
  };
} // namespace ausroll::mechanics
