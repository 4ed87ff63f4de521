/**
 * @file solution_writer.h
 * VTU/PVTU files per output step and the solution.pvd time series for ParaView.
 */
#pragma once

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <string>
#include <utility>
#include <vector>

namespace ausroll::io
{
  /** A named cell-wise field (one value per active cell of the local triangulation). */
  using CellField = std::pair<std::string, dealii::Vector<float>>;

  /** Scalar nodal fields stored in the components of a (ghosted) vector of the displacement DoFs:
      one name per component. */
  using NodalField
      = std::pair<std::vector<std::string>, const dealii::TrilinosWrappers::MPI::Vector *>;

  /**
   * Writes `<dir>/solution_NNNN.pvtu` + `solution_NNNN.<rank>.vtu` (displacement as a vector field,
   * cell fields, MPI rank) and rewrites `<dir>/solution.pvd` atomically after each output, so
   * that ParaView can always open the series written so far.
   */
  template <int dim>
  class SolutionWriter
  {
  public:
    /** Writer into @p directory (must exist). */
    SolutionWriter(const std::string &directory, const MPI_Comm comm);

    /**
     * Write output number @p counter at pseudo-time @p time. With @p deformed, points are placed at
     * their deformed position. Returns the name of the .pvtu file written.
     */
    std::string write(const unsigned int                           counter,
                      const double                                 time,
                      const dealii::DoFHandler<dim>               &dof_handler,
                      const dealii::Mapping<dim>                  &mapping,
                      const dealii::TrilinosWrappers::MPI::Vector &solution,
                      const std::vector<CellField>                &cell_fields,
                      const std::vector<NodalField>               &nodal_fields,
                      const bool                                   deformed);

    /** Pairs (time, .pvtu file) written so far (for restarts). */
    const std::vector<std::pair<double, std::string>> &records() const { return time_series; }

    /** Replace the list of pairs (time, file) (when resuming a run). */
    void set_records(const std::vector<std::pair<double, std::string>> &records);

  private:
    std::string                                 directory;
    MPI_Comm                                    comm;
    std::vector<std::pair<double, std::string>> time_series;
  };
} // namespace ausroll::io
