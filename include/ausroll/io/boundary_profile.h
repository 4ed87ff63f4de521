/**
 * @file boundary_profile.h
 * Deformed boundary shape in polar coordinates (`Postprocess/Boundary profile`): the rim of a
 * rolled disk as radius versus angle.
 */
#pragma once

#include <ausroll/io/output_parameters.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/trilinos_vector.h>

#include <string>

namespace ausroll::io
{
  /**
   * Writes, for every output, `<dir>/profile_NNNN.csv` with one row per displacement support
   * point (vertex and, for Q2, edge midpoint) on the boundaries `Postprocess/Boundary profile/
   * Boundary ids`, sorted by the polar angle of the reference position about `Center`. Columns:
   * `time,boundary_id,x,y,current_x,current_y,angle,radius,radial_displacement` with (x, y) the
   * reference position, current = reference + displacement, angle in degrees in [0, 360) (of the
   * reference position), radius = |current - Center| and radial_displacement = radius - |x -
   * Center|. Every rank contributes the points of its own cells; rank 0 removes duplicates (by
   * DoF index) and writes. Hanging nodes are fine: values come from the FE field, which is
   * continuous.
   */
  template <int dim>
  class BoundaryProfile
  {
  public:
    /** Profile described by @p parameters (inactive when no boundary id is given). */
    explicit BoundaryProfile(const BoundaryProfileParameters &parameters);

    /** True if no boundary is selected (nothing is written). */
    bool empty() const { return parameters.boundary_ids.empty(); }

    /** Write `profile_NNNN.csv` (NNNN = @p counter) for pseudo-time @p time into @p directory;
        @p solution must have ghost entries. */
    void write(const std::string                           &directory,
               const unsigned int                           counter,
               const double                                 time,
               const dealii::Mapping<dim>                  &mapping,
               const dealii::DoFHandler<dim>               &dof_handler,
               const dealii::TrilinosWrappers::MPI::Vector &solution) const;

  private:
    /** Boundary ids and centre (`Postprocess/Boundary profile`). */
    BoundaryProfileParameters parameters;
  };
} // namespace ausroll::io
