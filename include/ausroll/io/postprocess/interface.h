/**
 * @file interface.h
 * The postprocessor interface: everything ausroll writes about a converged state (history.csv
 * columns, contact/profile/probe CSV files, VTU cell and nodal fields) is computed by one
 * Postprocessor, and the scene runs them all, in a fixed order, through a PostprocessorSet.
 *
 * Conventions:
 *  - A postprocessor sees the state only through PostprocessInput, a read-only view of const
 *    references (mesh, DoFs, solution, residual, material points, model, loads, contact, time and
 *    step statistics). It never includes scene/ (io is below scene).
 *  - Every history column is computed once, by one postprocessor, under the name documented in
 *    its class comment (and in doc/manual.md, "Output"). The set refuses a column name that two
 *    postprocessors (or one, twice) produce: an internal error (std::logic_error, exit 4).
 *  - Columns, files and fields follow the order in which the postprocessors were added
 *    (PostprocessorSet::add); history.csv fixes its header with the first row, so the order is
 *    part of the output format.
 *  - initialize() is called after every mesh change (monitor points and probes are located
 *    again); execute() and write_files() only at converged states.
 */
#pragma once

#include <ausroll/contact/contact_operator.h>
#include <ausroll/io/history.h>
#include <ausroll/io/output_parameters.h>
#include <ausroll/io/solution_writer.h>
#include <ausroll/material/constitutive_model.h>
#include <ausroll/mechanics/boundary_conditions.h>
#include <ausroll/mechanics/generalized_plane_strain.h>
#include <ausroll/mechanics/material_point_storage.h>
#include <ausroll/thermal/thermal_system.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>
#include <string>
#include <vector>

namespace ausroll::io
{
  /**
   * Read-only view of the state a postprocessor may look at: the converged state after a load
   * step (or the initial state, or the last converged state before a failure is reported). Built
   * by the scene for every call; holds references only, so it must not outlive the call.
   */
  template <int dim>
  struct PostprocessInput
  {
    const dealii::Mapping<dim>                  &mapping;     ///< the (curved) mapping
    const dealii::DoFHandler<dim>               &dof_handler; ///< displacement DoFs (mesh, FE)
    const dealii::TrilinosWrappers::MPI::Vector &solution;    ///< displacement, with ghosts
    /** Residual f_int - f_ext of the last assembly, locally owned entries: at prescribed DoFs
        the reactions. */
    const dealii::TrilinosWrappers::MPI::Vector &residual;
    const mechanics::MaterialPointStorage<dim>  &material_points;     ///< committed states
    const material::ConstitutiveModel           &model;               ///< the material law
    const mechanics::BoundaryConditions<dim>    &boundary_conditions; ///< loads
    const contact::ContactOperator<dim>         &contact;             ///< nodes and dies

    double       time = 0.;             ///< pseudo-time of the state
    unsigned int step = 0;              ///< converged steps so far
    unsigned int newton_iterations = 0; ///< Newton iterations of the last step
    unsigned int cutbacks = 0;          ///< cutbacks of the last step
    double       wall_seconds = 0.;     ///< wall time since the start of the run
    /** The temperature field (thermal scenes; null when isothermal). */
    const thermal::ThermalSystem<dim> *thermal = nullptr;
    /** The out-of-plane stretch of generalized plane strain (null or inactive otherwise). */
    const mechanics::GeneralizedPlaneStrain *out_of_plane = nullptr;
  };

  /**
   * What a history column or VTU array measures: the quantity ("force", "length", "stress",
   * "angle", "count", "dimensionless", "pseudo-time", "wall time", ...) and its unit in the unit
   * system of the shipped scenes (mm, N, MPa, degrees, s; units are consistent: a scene in
   * other units reads them in its own). Written to history_units.csv and solution_units.csv.
   */
  struct Unit
  {
    std::string quantity; ///< e.g. "force"
    std::string unit;     ///< e.g. "N"; "1" for dimensionless numbers and counts
  };

  /**
   * One postprocessor (in the manner of ASPECT's Postprocess::Interface). Override what applies:
   * history columns (execute), files per output (write_files), VTU fields (cell_fields,
   * nodal_fields). All calls are collective: every rank calls them in the same order.
   */
  template <int dim>
  class Postprocessor
  {
  public:
    virtual ~Postprocessor() = default;

    /** Short name for messages (e.g. "monitor points"). */
    virtual std::string name() const = 0;

    /** After every mesh change (and before the first output): locate points, collect DoFs. May
        throw InputError naming the entry. */
    virtual void initialize(const PostprocessInput<dim> &input) { (void)input; }

    /** Append this postprocessor's history columns (name, value) to @p row. */
    virtual void execute(const PostprocessInput<dim> &input, HistoryRow &row) const
    {
      (void)input;
      (void)row;
    }

    /** Write this postprocessor's files of output number @p counter into @p directory. */
    virtual void write_files(const PostprocessInput<dim> &input,
                             const std::string           &directory,
                             const unsigned int           counter)
    {
      (void)input;
      (void)directory;
      (void)counter;
    }

    /** Append cell-wise VTU fields (one value per active cell of the local mesh). */
    virtual void cell_fields(const PostprocessInput<dim> &input,
                             std::vector<CellField>      &fields) const
    {
      (void)input;
      (void)fields;
    }

    /** Append nodal VTU fields; the vectors must live until the next write_files(). Called after
        write_files() of the same output. */
    virtual void nodal_fields(std::vector<NodalField> &fields) const { (void)fields; }

    /** Quantity and unit of the history column or VTU array @p name this postprocessor
        produces (documented with the column in the class comment). */
    virtual Unit unit(const std::string &name) const
    {
      (void)name;
      return {};
    }
  };

  /**
   * The postprocessors of a run, in a fixed order, and the VTU writer they feed. The scene adds
   * them once (its only output wiring), calls initialize() after every mesh change,
   * history_row() after every converged step and write_output() at every output.
   */
  template <int dim>
  class PostprocessorSet
  {
  public:
    /** Set writing as `Output` says (`Write VTU`, `Deformed mesh`) on communicator @p comm. */
    PostprocessorSet(const OutputParameters &output, const MPI_Comm comm);

    /** Append @p postprocessor: its columns, files and fields follow those added before. */
    void add(std::unique_ptr<Postprocessor<dim>> postprocessor);

    /** The postprocessors, in order. */
    const std::vector<std::unique_ptr<Postprocessor<dim>>> &postprocessors() const
    {
      return members;
    }

    /** Initialize every postprocessor (after a mesh change). */
    void initialize(const PostprocessInput<dim> &input);

    /**
     * The history row of @p input: every postprocessor's columns in order. Throws
     * std::logic_error (internal error) if a column name occurs twice, naming the
     * postprocessors that produce it. After open_vtu_writer(), the first row also writes
     * `history_units.csv` (rank 0) into the output directory: the header `column,quantity,unit`
     * and one line per history column in order (Postprocessor::unit(); "unknown" if its
     * postprocessor declares none).
     */
    HistoryRow history_row(const PostprocessInput<dim> &input);

    /** Open the VTU writer into @p directory (which must exist; call once, after the output
        directory has been prepared); the units files are written there too. */
    void open_vtu_writer(const std::string &directory);

    /**
     * Output number @p counter into @p directory: every postprocessor's files in order, then (with
     * `Output/Write VTU`) one VTU/PVTU with the displacement and every cell and nodal field; the
     * first VTU output also writes `solution_units.csv` (rank 0): `array,quantity,unit` per VTU
     * array.
     */
    void write_output(const PostprocessInput<dim> &input,
                      const std::string           &directory,
                      const unsigned int           counter);

    /** Pairs (time, .pvtu file) written so far (for checkpoints). */
    const std::vector<std::pair<double, std::string>> &vtu_records() const;

    /** Replace the pairs (time, .pvtu file) (when resuming). */
    void set_vtu_records(const std::vector<std::pair<double, std::string>> &records);

  private:
    OutputParameters                                 output;  ///< `Output`
    MPI_Comm                                         comm;    ///< communicator
    std::vector<std::unique_ptr<Postprocessor<dim>>> members; ///< in order
    std::unique_ptr<SolutionWriter<dim>>             writer;  ///< VTU/PVTU/PVD
    std::string directory;                     ///< output directory (open_vtu_writer())
    bool        history_units_written = false; ///< history_units.csv written
    bool        vtu_units_written = false;     ///< solution_units.csv written
  };
} // namespace ausroll::io
