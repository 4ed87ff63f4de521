/**
 * @file boundary_conditions.h
 * Prescribed displacements and surface loads on workpiece boundaries (`Boundary conditions`).
 */
#pragma once

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/component_mask.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>
#include <set>
#include <string>
#include <vector>

namespace ausroll::mechanics
{
  /** Kind of a boundary condition (`Type`). */
  enum class BoundaryConditionType
  {
    fixed,        ///< all displacement components zero
    displacement, ///< selected components follow `Value` (one expression per selected component)
    pressure, ///< normal pressure `Value` (positive pushes into the body): on the deformed surface
              ///< (follower load) unless `Model/Kinematics = small strain`
    traction  ///< traction vector `Value` (dim expressions) per reference area (dead load)
  };

  /** One entry `Boundary conditions/Condition N`. */
  struct BoundaryCondition
  {
    dealii::types::boundary_id id = 0;                              ///< `Boundary id`
    BoundaryConditionType      type = BoundaryConditionType::fixed; ///< `Type`
    std::string                components = "x, y";                 ///< `Components` (displacement)
    std::string                value = "0"; ///< `Value` expressions, ';'-separated
  };

  /** Parameters of subsection `Boundary conditions`. */
  struct BoundaryConditionParameters
  {
    static constexpr unsigned int  max_conditions = 8; ///< declared `Condition 0..7` subsections
    std::vector<BoundaryCondition> conditions;         ///< the first `Number of conditions`

    /** Declare subsection `Boundary conditions`. */
    static void declare_parameters(dealii::ParameterHandler &prm);
    /** Read subsection `Boundary conditions`. */
    void parse_parameters(dealii::ParameterHandler &prm);
    /** The boundary ids with prescribed displacements (`fixed` or `displacement`). */
    std::set<unsigned int> held_boundaries() const;
  };

  /**
   * The boundary conditions of a scene, with their parsed value functions of (x, y[, z], t).
   */
  template <int dim>
  class BoundaryConditions
  {
  public:
    /**
     * InputError naming the condition's `Value` if one of its expressions is not finite (nan,
     * inf, e.g. t/0 or sqrt(-1-t)) at a vertex of its boundary at one of @p times.
     */
    void check_values(const dealii::Triangulation<dim> &triangulation,
                      const std::vector<double>        &times) const;
    /** Parse the expressions of @p parameters; InputError names a bad `Value` or `Components`. */
    explicit BoundaryConditions(const BoundaryConditionParameters &parameters);

    /**
     * Add to @p constraints the Dirichlet conditions for a Newton increment at time @p time:
     * delta_u_i = g_i(x, time) - u_i for every constrained DoF in @p constraints' locally relevant
     * set, where u is @p current (ghosted).
     */
    void add_increment_constraints(const dealii::DoFHandler<dim>               &dof_handler,
                                   const double                                 time,
                                   const dealii::TrilinosWrappers::MPI::Vector &current,
                                   dealii::AffineConstraints<double>           &constraints) const;

    /** True if @p id carries a pressure or traction load. */
    bool has_surface_load(const dealii::types::boundary_id id) const;

    /**
     * Dead surface traction (force per reference area) on boundary @p id at reference point @p X
     * and time @p time: the sum of the `traction` conditions on @p id.
     */
    dealii::Tensor<1, dim> dead_traction(const dealii::types::boundary_id id,
                                         const dealii::Point<dim>        &X,
                                         const double                     time) const;

    /**
     * Pressure (positive pushes into the body) on boundary @p id at reference point @p X and time
     * @p time: the sum of the `pressure` conditions on @p id. The assembler applies it on the
     * reference surface (small strain) or on the deformed surface (follower load).
     */
    double pressure(const dealii::types::boundary_id id,
                    const dealii::Point<dim>        &X,
                    const double                     time) const;

    /**
     * Reference-surface traction: dead_traction() - pressure() @p normal, @p normal being the
     * outward unit normal of the reference surface (the small-strain surface load).
     */
    dealii::Tensor<1, dim> traction(const dealii::types::boundary_id id,
                                    const dealii::Point<dim>        &X,
                                    const dealii::Tensor<1, dim>    &normal,
                                    const double                     time) const;

    /** Names and current values of the pressure loads, for the history (`pressure_<id>`). */
    std::vector<std::pair<std::string, double>> pressure_values(const double time) const;

  private:
    struct Entry
    {
      BoundaryCondition                            condition;
      dealii::ComponentMask                        mask;
      std::unique_ptr<dealii::FunctionParser<dim>> function; ///< dim components (unused ones 0)
    };
    std::vector<Entry> entries; ///< one per condition
  };
} // namespace ausroll::mechanics
