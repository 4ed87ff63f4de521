/**
 * @file thermal_system.h
 * The temperature field of a thermal scene: DoFs, matrix, vectors and the backward-Euler step of
 * the heat equation on the workpiece mesh.
 */
#pragma once

#include <ausroll/contact/contact_operator.h>
#include <ausroll/material/material_point.h>
#include <ausroll/thermal/thermal_parameters.h>

#include <deal.II/base/function_parser.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/base/quadrature_point_data.h>
#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <array>
#include <functional>
#include <memory>
#include <vector>

namespace ausroll::thermal
{
  /**
   * The heat equation of the workpiece, rho0 c dT/dt = Div(K Grad T) + r0, in the reference
   * configuration (the mesh the mechanics is assembled on), per unit reference volume:
   * rho0 c is conserved with the mass, r0 = beta dW_p/dt is the plastic heating of the material
   * points (ThermalExpansionModel's plastic work per reference volume), and K = J F^-1 k F^-T is
   * the exact pull-back of Fourier conduction q = -k grad T in the deformed body (the mechanics'
   * deformation gradient F at the step's end; small strain: K = k I). Boundary fluxes act on the
   * reference surface (an approximation where the surface stretches). The field is a scalar FE_Q
   * of the displacement's degree on the same (distributed) mesh and quadrature, so that its
   * temperature at the material points is exact at the points the mechanics evaluates.
   *
   * Time integration: backward Euler; the properties k(T), rho(T), c(T) at the temperature of the
   * step's start (linear in T per step). Linear system: CG with algebraic multigrid (symmetric
   * positive definite).
   */
  template <int dim>
  class ThermalSystem
  {
  public:
    using Vector = dealii::TrilinosWrappers::MPI::Vector;
    using PointStorage = dealii::CellDataStorage<typename dealii::Triangulation<dim>::cell_iterator,
                                                 material::MaterialPoint>;

    /** What the heat equation needs of the mechanics at a point. */
    struct Kinematics
    {
      /** Factor turning the reference area element into the volume element (2 pi x axisymmetric,
          the thickness in plane strain/stress, 1 in 3D). */
      std::function<double(const dealii::Point<dim> &)> volume_factor;
      /** F (3x3) from Grad u, u and X; empty for small strain (K = k I). */
      std::function<dealii::Tensor<2, 3>(const dealii::Tensor<2, dim> &,
                                         const dealii::Tensor<1, dim> &,
                                         const dealii::Point<dim> &)>
          deformation_gradient;
    };

    /** A closed contact node (its displacement DoF, area, die and frictional work). */
    using Contact = typename contact::ContactOperator<dim>::HeatContact;

    /** Heat flows of the last step (N mm/s; 2D: per the model's thickness, axisymmetric: full
        circumference). */
    struct Balance
    {
      double              plastic_heat = 0.; ///< int beta dW_p/dt dV
      std::vector<double> boundary_heat;     ///< into the body, per `Thermal/Condition k`
      std::vector<double> die_heat; ///< into the body from each die (conductance + friction)
    };

    ThermalSystem(const ThermalParameters                           &parameters,
                  dealii::parallel::distributed::Triangulation<dim> &triangulation,
                  const dealii::Mapping<dim>                        &mapping,
                  const unsigned int                                 degree,
                  const dealii::Quadrature<dim>                     &quadrature,
                  Kinematics                                         kinematics,
                  const unsigned int                                 n_dies,
                  const MPI_Comm                                     comm);

    /** Distribute DoFs, build the sparsity pattern and size the vectors (after every mesh
        change, before finish_refinement()). */
    void setup();

    /** Throw InputError naming `Thermal/Die temperatures` if a die temperature is not finite
        at 101 times in [0, @p end_time]. */
    void check_die_temperatures(const double end_time) const;

    /** T = `Thermal/Initial temperature` (not when resuming). */
    void initialize();

    /**
     * One backward-Euler step to time @p t of size @p dt: plastic heating from the material
     * points (trial minus committed plastic work; call before they are committed), conduction
     * pulled back with the displacement @p displacement on @p displacement_dofs.
     */
    void solve_step(const double                   t,
                    const double                   dt,
                    const dealii::DoFHandler<dim> &displacement_dofs,
                    const Vector                  &displacement,
                    const PointStorage            &points,
                    const std::vector<Contact>    &contacts);

    /**
     * Make @p stage_conditions the boundary conditions of the next solves (a process stage's:
     * the `Thermal` conditions with other values or heat transfer coefficients; same boundary
     * ids and types). Expressions that cannot be parsed are an InputError naming @p entry.
     */
    void set_conditions(const std::vector<ThermalCondition> &stage_conditions,
                        const std::string                   &entry);

    /** Accept the last solve: committed_temperature = temperature. */
    void commit();

    /** Discard solves since the last commit: temperature = committed_temperature. */
    void restore();

    /** Write the temperature at the material points into their trial states (and, with
        @p committed_too, their committed states). */
    void set_point_temperatures(PointStorage &points, const bool committed_too) const;

    /**
     * After the heat solve of a step the points hold the temperature of the next step. For a
     * solve at the time of the committed state (the re-equilibration after a mesh change,
     * Scene::adapt_mesh) make the temperature the points' states were evaluated at
     * (MaterialState::evaluation_temperature) their trial and committed temperature, so that the
     * solve carries no thermal or transformation increment; release_point_temperatures() writes
     * the next step's temperature back.
     */
    void hold_point_temperatures(PointStorage &points) const;

    /** The temperature at the material points into their trial and committed states, their
        evaluation temperatures kept (after hold_point_temperatures()). */
    void release_point_temperatures(PointStorage &points) const;

    /** @name Mesh changes and checkpoints (parallel::distributed::SolutionTransfer) */
    //@{
    /** Before Triangulation::execute_coarsening_and_refinement(). */
    void prepare_refinement();
    /** After it (and after setup()): the interpolated temperature. */
    void finish_refinement();
    /** Before Triangulation::save() (after the mechanics' own transfers were attached). */
    void prepare_serialization();
    /** After Triangulation::load() and setup(), in the order of prepare_serialization(). */
    void deserialize();
    //@}

    /** Minimum, maximum and volume mean of the nodal temperatures (all ranks). */
    std::array<double, 3> statistics() const;

    const ThermalParameters &parameters; ///< `Thermal`
    MPI_Comm                 comm;       ///< communicator

    dealii::FE_Q<dim>       fe;            ///< scalar FE_Q(degree)
    dealii::DoFHandler<dim> dof_handler;   ///< temperature DoFs
    dealii::IndexSet        owned_dofs;    ///< locally owned
    dealii::IndexSet        relevant_dofs; ///< locally relevant
    Vector                  temperature;   ///< T of the last solve (ghosted)
    /** T of the last converged (committed) step, T_n of the next solve (ghosted). */
    Vector committed_temperature;
    /** Largest nodal change of T made by the last solve (against the T before it). */
    double  last_change = 0.;
    Vector  temperature_rate; ///< (T - T_n) / dt of the last step (ghosted)
    Balance balance;          ///< heat flows of the last step

  private:
    /** Call @p write(point, T) for every locally owned material point with the temperature
        field's value T there. */
    template <typename Write>
    void write_point_temperatures(PointStorage &points, const Write &write) const;

    /** Assemble the backward-Euler system (@p residual null) or, with @p residual, the
        unconstrained residual of the converged step at @p T (reactions of prescribed
        temperatures). */
    void assemble(const double                   t,
                  const double                   dt,
                  const dealii::DoFHandler<dim> &displacement_dofs,
                  const Vector                  &displacement,
                  const PointStorage            &points,
                  const Vector                  &T_old,
                  const std::vector<Contact>    &contacts,
                  Vector                        *residual);

    /** Contact conductance and friction heat at the closed nodes (nodal terms, as the contact
        forces are nodal): into the matrix and rhs, or (with @p residual) the residual and the
        heat per die. */
    void add_contact_terms(const double                   t,
                           const double                   dt,
                           const dealii::DoFHandler<dim> &displacement_dofs,
                           const std::vector<Contact>    &contacts,
                           Vector                        *residual);

    /** Hanging nodes and prescribed temperatures at time @p t. */
    void make_constraints(const double t);

    dealii::parallel::distributed::Triangulation<dim> &triangulation; ///< the workpiece mesh
    const dealii::Mapping<dim>                        &mapping;       ///< its mapping
    const dealii::Quadrature<dim>                      quadrature;    ///< the mechanics'
    Kinematics                                         kinematics;    ///< volume factor, F
    dealii::AffineConstraints<double>                  constraints;   ///< hanging + Dirichlet
    dealii::TrilinosWrappers::SparseMatrix             matrix;        ///< M/dt + K (+ convection)
    Vector                                             rhs;           ///< owned
    /** The boundary conditions in force: `Thermal/Condition k`, or a stage's (set_conditions()). */
    std::vector<ThermalCondition>                             conditions;
    std::vector<std::unique_ptr<dealii::FunctionParser<dim>>> values; ///< per condition, of t
    std::vector<std::unique_ptr<dealii::FunctionParser<1>>>   die_temperatures; ///< per die, of t
    std::unique_ptr<dealii::parallel::distributed::SolutionTransfer<dim, Vector>> transfer;
  };
} // namespace ausroll::thermal
