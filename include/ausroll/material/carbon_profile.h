/**
 * @file carbon_profile.h
 * The carbon content of the workpiece (`Phases/Carbon content`): an expression of the position
 * and of the depth below the initial surface, or a table of carbon against depth; evaluated once
 * at the material points.
 */
#pragma once

#include <ausroll/geometry/boundary_depth.h>
#include <ausroll/material/material_point.h>

#include <deal.II/base/function_parser.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/base/quadrature_point_data.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/tria.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ausroll::material
{
  class PropertyTable;

  /**
   * `Phases/Carbon content` C (wt%) of a point of the initial workpiece:
   * - an expression of x, y (z in 3D) and `depth`, the distance below the initial surface
   *   (geometry::BoundaryDepth of the boundaries `Phases/Case boundaries`: the nearest point of
   *   their exact outline, along its normal), e.g. the diffusion profile
   *   `0.2 + 0.7 * erfc(depth / 0.6)` (surface 0.9, core 0.2 wt%, 0.6 mm = 2 sqrt(D t));
   * - `file: NAME.csv`: a table of two columns depth (mm), C (wt%), depths strictly increasing,
   *   linear between the rows and constant beyond the first and the last (NAME relative to the
   *   `.prm` file's folder).
   * The depth is computed only if the profile uses it.
   */
  template <int dim>
  class CarbonProfile
  {
  public:
    /**
     * The profile @p text (the entry's value) for the workpiece @p triangulation, depth below
     * the boundaries @p case_boundaries (used only if the profile needs a depth; an id that is
     * not a boundary of the workpiece is an InputError naming `Phases/Case boundaries`);
     * @p input_directory resolves `file:` tables. Throws InputError naming
     * `Phases/Carbon content` if the expression does not parse or the table is malformed.
     */
    CarbonProfile(const std::string                &text,
                  const dealii::Triangulation<dim> &triangulation,
                  const std::vector<unsigned int>  &case_boundaries,
                  const std::string                &input_directory);
    ~CarbonProfile();

    /** True if @p text (an entry value) uses the depth: a table, or the word `depth`. */
    static bool uses_depth(const std::string &text);

    /** C (wt%) at the point @p p of the initial workpiece. */
    double value(const dealii::Point<dim> &p) const;

    /** The depth below the case boundaries (nullptr if the profile does not use it). */
    const geometry::BoundaryDepth<dim> *depth() const { return boundary_depth.get(); }

  private:
    std::string                                   text;
    std::unique_ptr<geometry::BoundaryDepth<dim>> boundary_depth;
    std::unique_ptr<dealii::FunctionParser<dim>>  expression; ///< of x, y, (z,) depth (the time)
    std::unique_ptr<PropertyTable>                table;      ///< C against depth
  };

  /**
   * Set the carbon content of every material point of the locally owned cells of
   * @p dof_handler (at the points of @p quadrature mapped by @p mapping) to @p profile, and the
   * phases to all austenite (committed and trial). Collective: an InputError naming
   * `Phases/Carbon content` (and the profile @p text) on every rank if C leaves 0 to 2.1 wt%
   * anywhere.
   */
  template <int dim>
  void initialize_carbon(const CarbonProfile<dim>               &profile,
                         const std::string                      &text,
                         const dealii::Mapping<dim>             &mapping,
                         const dealii::FiniteElement<dim>       &fe,
                         const dealii::Quadrature<dim>          &quadrature,
                         const dealii::DoFHandler<dim>          &dof_handler,
                         dealii::CellDataStorage<typename dealii::Triangulation<dim>::cell_iterator,
                                                 MaterialPoint> &points,
                         const MPI_Comm                          comm);
} // namespace ausroll::material
