/**
 * @file assembler.h
 * Cell loop of the equilibrium equations: internal forces, surface loads, consistent tangent.
 */
#pragma once

#include <ausroll/contact/nodal_row_transform.h>
#include <ausroll/material/constitutive_model.h>
#include <ausroll/mechanics/boundary_conditions.h>
#include <ausroll/mechanics/generalized_plane_strain.h>
#include <ausroll/mechanics/material_point_storage.h>
#include <ausroll/mechanics/planar_kinematics.h>
#include <ausroll/mechanics/terms/interface.h>
#include <ausroll/mechanics/terms/internal_force.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <vector>

namespace ausroll::mechanics
{
  using contact::NodalRowTransform;
  using contact::RowTransforms;

  /** The vectors and matrices one assembly fills. */
  struct AssemblyTargets
  {
    /** f_int - f_ext with only hanging-node constraints applied: entries at constrained DoFs are
        the reactions (required). */
    dealii::TrilinosWrappers::MPI::Vector *residual = nullptr;
    /** External forces (surface loads), hanging-node condensed (required). */
    dealii::TrilinosWrappers::MPI::Vector *external_force = nullptr;
    /** Residual condensed with the Newton constraints and row transforms (homogeneous): the
        out-of-balance force of the free equations (optional). */
    dealii::TrilinosWrappers::MPI::Vector *free_residual = nullptr;
    /** Tangent matrix condensed with the Newton constraints (optional). */
    dealii::TrilinosWrappers::SparseMatrix *matrix = nullptr;
    /** Right-hand side -r of the Newton system, with inhomogeneities (with matrix). */
    dealii::TrilinosWrappers::MPI::Vector *rhs = nullptr;
    /** Generalized plane strain: int P_zz dV and, with matrix, the border k_ue (its `column`,
        zeroed by the caller), k_eu (`row`, zeroed) and k_ee (null: not assembled). */
    GeneralizedPlaneStrain *out_of_plane = nullptr;
  };

  /**
   * The cell part (internal forces, material tangent, smallest det F) of the last assembly, which
   * the next assembly reuses when it is at the same state: a contact status change (nested active
   * set at a converged pass, active set at an iterate) changes the constraints and the friction
   * row transforms but neither the displacement nor the material states, and re-assembling
   * the cells would only repeat the material evaluations bit for bit. The Assembler decides:
   * same displacement (bitwise, ghosts included) and out-of-plane stretch, same time, same mesh,
   * the tangent when asked for, and the same @ref state. The owner of the material points
   * increments @ref state whenever they change other than through an assembly (commit, restore,
   * transfer to a new mesh, re-basing): the trial states are then those of the cached evaluation.
   * Face loads, row transforms and the condensation are done anew at every assembly. Kept only
   * while it needs at most @ref max_bytes (3D meshes: usually off).
   */
  struct AssemblyCache
  {
    std::uint64_t       state = 0;             ///< the owner's counter of material-state changes
    std::size_t         max_bytes = 64u << 20; ///< largest cache kept (bytes)
    bool                valid = false;         ///< the arrays hold an assembly
    bool                with_matrix = false;   ///< ... with the cell matrices
    std::uint64_t       cached_state = 0;      ///< @ref state of the cached assembly
    double              time = 0.;             ///< its time
    double              stretch = 1.; ///< its out-of-plane stretch (generalized plane strain)
    std::vector<double> solution;     ///< its displacement (local and ghost entries)
    std::vector<double> matrices, residuals; ///< cell matrices and residuals by active cell index
    std::vector<double> min_jacobian;        ///< smallest det F of each cell
    /** Generalized plane strain: each cell's k_ue, k_eu (n_dofs each), int P_zz dV and k_ee. */
    std::vector<double> out_of_plane;
    unsigned long       hits = 0, misses = 0; ///< statistics (reused / computed assemblies)
    /** The material points by active cell index (quadrature points in order) as at @ref state
        @ref points_state: built once per state instead of a CellDataStorage look-up (a map of
        cell ids and a vector of shared pointers) per cell and assembly. */
    std::vector<material::MaterialPoint *> points;
    std::uint64_t                          points_state = 0;
    bool                                   points_valid = false;
    /** The owner's counter of sparsity-pattern changes (a new matrix): the slot tables below
        belong to one pattern. */
    std::uint64_t pattern = 0;
    /** Where each cell's matrix entries live in the matrix of @ref slots_pattern: for the cell of
        active index c and local row i, slot_rows[c n + i] is the row's value array in the
        Epetra matrix (nullptr: row not owned here, the cell takes deal.II's path) and
        slot_columns[(c n + i) n + j] the position of column j in it. Cells without constrained
        DoFs add their matrix and right-hand side there directly (the same sums in the same
        order as AffineConstraints::distribute_local_to_global, without its sorting and
        Epetra's row and column searches). */
    std::vector<double *>     slot_rows;
    std::vector<std::int32_t> slot_columns;
    std::vector<std::int32_t> slot_rhs; ///< local index of each cell row in the rhs vector
    std::uint64_t             slots_pattern = 0;
    const void               *slots_matrix = nullptr;
    bool                      slots_valid = false;
  };

  /** Outcome of an assembly, identical on all MPI ranks. */
  struct AssemblyStatus
  {
    bool        ok = true;         ///< false: material failure or inverted element somewhere
    double      min_jacobian = 1.; ///< smallest det F over all quadrature points
    std::string message;           ///< reason when !ok (from the rank that failed)
  };

  /**
   * Assembles residual and tangent of quasi-static equilibrium, div P = 0 in the reference
   * configuration, for any ConstitutiveModel. A dealii::WorkStream driver (deal.II's step-44 shape,
   * the term list after ASPECT's Assemblers::Manager) over a list of AssemblyTerm objects
   * (mechanics/terms/) built once in the constructor: InternalForce (quadrature loop, material
   * points, internal force, material tangent; with the F-bar policy FBar of terms/f_bar.h) and
   * the face loads (terms/face_loads.h, follower pressure in terms/follower_pressure.h). The
   * terms are specialised once for the hoop entry of the kinematics (NoHoopEntry,
   * AxisymmetricHoopEntry in planar_kinematics.h), so neither the driver nor a term tests the
   * planar model. Per cell on `DEAL_II_NUM_THREADS` threads the worker assemble_one_cell() calls
   * each term once with its own scratch, then the row-transform part; a copier adds each cell
   * to the Trilinos targets through AffineConstraints::distribute_local_to_global in cell order,
   * so the sums are the serial ones whatever the number of threads.
   *
   * Surface loads: `traction` conditions are dead loads per reference area. `pressure` conditions
   * act on the reference surface for a small-strain model and on the deformed surface otherwise
   * (follower load): the nominal traction is t0 = -p J F^-T N, computed from the deformed tangent
   * of the face, a = F T (T the reference unit tangent): t0 dA = -p (a_y, -a_x) dL, times the hoop
   * stretch r / R in axisymmetric models (the deformed area element is 2 pi r dl). Its derivative
   * (the load stiffness, non-symmetric) enters the tangent, so Newton stays quadratic. Plane
   * stress: the change of thickness is not included (force per deformed length and reference
   * thickness; the thickness stretch lives at the material points, not on the faces);
   * generalized plane strain: times the global lambda (and dr/dlambda into the border). 3D models
   * (dim = 3): dead tractions only, a non-zero follower pressure throws (not implemented yet).
   *
   * Volumetric locking (`Model/Volumetric locking treatment = F-bar`, de Souza Neto, Peric,
   * Dutko and Owen 1996): the material points see F_bar = s F with s = (J0 / J)^(1/n), J = det F
   * at the point and J0 = det F at the centre of the cell for Q1 (for Q2 and higher the volume
   * average of det F over the cell, the mean dilatation: one centre value leaves the volumetric
   * modes of Q2 that vanish at the centre free, and a flat-punch limit load came out 7 % low),
   * n = PlanarKinematics::
   * volumetric_dimensions(...) (n = 2 scales only the in-plane block of F, so F_bar_zz = 1 stays
   * plane strain; n = 3 scales the whole F, hoop stretch included). Exception: Q2 and higher in
   * plane strain use n = 3 on the whole F (F_bar_zz = s, like Hughes' B-bar with eps_bar_zz =
   * (theta_0 - theta) / 3): with the in-plane scaling the volume correction changes the 3D
   * deviatoric strain, and Q2 came out 7 % too soft in the Prandtl punch (0.928 p_lim; isotropic:
   * 0.998). Plane stress always uses n = 2 (F_zz comes from sigma_zz = 0). The internal force is
   * the spatial virtual work of sigma(F_bar) on the current configuration, int sigma_bar : grad_x
   * dv = int (J s / J0) P(F_bar) : Grad dV. The exact tangent has the extra non-symmetric term of
   * the cell-centre gradient. For small strain the same construction with F_bar = F + (tr(F0 - I) -
   * tr(F - I)) / n I_n is the B-bar method (tr(F0 - I) at the centre for Q1, averaged over the cell
   * for higher degrees).
   */
  template <int dim>
  class Assembler
  {
  public:
    /**
     * Assembler for the element @p fe with @p n_q_points_1d Gauss points per direction and the
     * treatment @p locking of volumetric locking (`Model/Volumetric locking treatment`).
     */
    Assembler(const dealii::Mapping<dim>        &mapping,
              const dealii::FiniteElement<dim>  &fe,
              const unsigned int                 n_q_points_1d,
              const PlanarKinematics<dim>       &kinematics,
              const material::ConstitutiveModel &model,
              const BoundaryConditions<dim>     &boundary_conditions,
              const VolumetricLocking            locking = VolumetricLocking::none);

    ~Assembler();

    /** The cell quadrature (material points live at its points). */
    const dealii::Quadrature<dim> &quadrature() const { return cell_quadrature; }

    /**
     * Evaluate all material points of the locally owned cells at the displacement @p solution
     * (ghosted) and time @p time (trial states are overwritten), and fill @p targets.
     * @p hanging holds the hanging-node constraints, @p newton the constraints of the Newton
     * increment (hanging nodes, Dirichlet, contact; inhomogeneous); @p row_transforms may be null.
     * With a @p cache, the cell part of the last assembly is reused when the state is the same
     * (see AssemblyCache; the targets are then identical to a full assembly's) and this
     * assembly's cell part is kept for the next.
     */
    AssemblyStatus assemble(const dealii::DoFHandler<dim>               &dof_handler,
                            const dealii::TrilinosWrappers::MPI::Vector &solution,
                            const double                                 time,
                            MaterialPointStorage<dim>                   &material_points,
                            const dealii::AffineConstraints<double>     &hanging,
                            const dealii::AffineConstraints<double>     &newton,
                            const RowTransforms<dim>                    *row_transforms,
                            const AssemblyTargets                       &targets,
                            AssemblyCache                               *cache = nullptr) const;

    /**
     * The deformation gradients the material points of @p cell see at the displacement
     * @p solution (ghosted): F, or F-bar with the volumetric correction of assemble() (cell centre
     * for Q1, cell average for higher degrees; B-bar for small strain). Used to re-base
     * transferred material states (ConstitutiveModel::rebase) so that the next evaluation returns
     * the transferred stress.
     */
    std::vector<dealii::Tensor<2, 3>> material_deformation_gradients(
        const typename dealii::DoFHandler<dim>::active_cell_iterator &cell,
        const dealii::TrilinosWrappers::MPI::Vector                  &solution) const;

  private:
    using ActiveCell = typename dealii::DoFHandler<dim>::active_cell_iterator;

    struct Setup;       ///< what one assembly call needs besides the terms' inputs (targets, cache)
    struct ScratchData; ///< one scratch object per term, one ScratchData per thread
    using CopyData = LocalSystem; ///< local matrix and vectors of one cell (WorkStream copy)

    /**
     * WorkStream worker: the terms of @p cell into @p copy (residual = internal - external
     * force): the cached terms (or their cached sum), then the others, then the row transforms.
     */
    void assemble_one_cell(const ActiveCell &cell,
                           const Setup      &setup,
                           ScratchData      &scratch,
                           CopyData         &copy) const;

    /** Row-transform part: friction row transforms on the rows of the cell's nodes (free
        residual and tangent; the residual itself stays untransformed: reactions). */
    void apply_row_transforms(const Setup &setup, CopyData &copy) const;

    /** Row-transform part, global: the constant offsets of the row transforms (shear friction)
        into free residual and rhs, once per node by the owner of its first DoF. */
    void add_row_transform_offsets(const dealii::DoFHandler<dim> &dof_handler,
                                   const Setup                   &setup) const;

    /** Decide whether this assembly reuses the cell part of @p cache (same state, see
        AssemblyCache) or computes it and stores it there; sets setup.reuse / setup.store. */
    void prepare_cache(const dealii::DoFHandler<dim>               &dof_handler,
                       const dealii::TrilinosWrappers::MPI::Vector &solution,
                       const double                                 time,
                       AssemblyCache                               *cache,
                       Setup                                       &setup) const;

    /** Add one cell to the targets (serial, in cell order: the WorkStream copier); gathers the
        outcome (failure, min det F) in @p setup. */
    void copy_local_to_global(const CopyData &copy, Setup &setup) const;

    const dealii::Mapping<dim>        &mapping;
    const dealii::FiniteElement<dim>  &fe;
    const dealii::QGauss<dim>          cell_quadrature;
    const dealii::QGauss<dim - 1>      face_quadrature;
    const PlanarKinematics<dim>       &kinematics;
    const material::ConstitutiveModel &model;
    const BoundaryConditions<dim>     &boundary_conditions;
    const VolumetricLocking            locking; ///< `Model/Volumetric locking treatment`
    /** Generalized plane strain: the cells' border of the Newton system is assembled too. */
    const bool out_of_plane;
    /** The element's tables (component of each shape function, DoFs of each node). */
    const AssemblyLayout layout;

    /** The internal-force term (also asked for material_deformation_gradients()). */
    const InternalForce<dim> *internal_force = nullptr;
    /** The terms in the order they add to a cell: the cached ones first (built once). */
    std::vector<std::unique_ptr<const AssemblyTerm<dim>>> terms;
    /** Number of leading terms in @ref terms that form the cached cell part. */
    unsigned int n_cached_terms = 0;

    /** On one thread (DEAL_II_NUM_THREADS=1) the cells are assembled in a plain loop with this
        scratch and copy, kept from call to call (WorkStream builds both anew per call). */
    mutable std::unique_ptr<ScratchData> kept_scratch;
    mutable std::unique_ptr<CopyData>    kept_copy;

    /** Fill @p cache's slot tables for the matrix in @p targets when they are not those of its
        current pattern (and fit into its max_bytes); sets setup.slots when they can be used. */
    void prepare_slots(const dealii::DoFHandler<dim> &dof_handler,
                       AssemblyCache                 *cache,
                       Setup                         &setup) const;
  };
} // namespace ausroll::mechanics
