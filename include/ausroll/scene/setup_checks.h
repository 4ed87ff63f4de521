/**
 * @file setup_checks.h
 * The checks of a new run before anything is written (input errors that only the mesh, the loads
 * and the dies together reveal).
 */
#pragma once

#include <ausroll/contact/contact_operator.h>
#include <ausroll/mechanics/boundary_conditions.h>
#include <ausroll/mechanics/memory_estimate.h>
#include <ausroll/scene/scene_parameters.h>

#include <deal.II/grid/tria.h>

namespace ausroll::scene
{
  /**
   * InputError (naming the entry) unless: every boundary-id entry of @p parameters
   * (`Boundary conditions/Condition N/Boundary id`, `Contact/Die N/Candidate boundaries`,
   * `Postprocess/Reaction boundaries`, `Postprocess/Boundary profile/Boundary ids`) is an id of
   * @p triangulation; an axisymmetric body lies off the axis; the loads of @p boundary_conditions
   * are finite and the dies of @p contact plausible at a bounded number of sampled times (all
   * step times for up to 256 steps: the check costs the same for any `Loading/Number of steps`).
   */
  template <int dim>
  void check_setup(const SceneParameters                    &parameters,
                   const dealii::Triangulation<dim>         &triangulation,
                   const mechanics::BoundaryConditions<dim> &boundary_conditions,
                   const contact::ContactOperator<dim>      &contact);

  /**
   * The sizes of a discretisation of @p n_cells active cells in dim dimensions with the
   * element, quadrature, linear solver and line probes of @p parameters, checked before any DoF
   * or material point is allocated: InputError if the DoFs exceed geometry::max_dofs or the
   * estimated memory exceeds the machine's (mechanics::require_memory()), naming the entries
   * that set the size with their values. Returns the estimate (printed by --check-input).
   */
  template <int dim>
  mechanics::MemoryEstimate check_sizes(const SceneParameters &parameters, double n_cells);
} // namespace ausroll::scene
