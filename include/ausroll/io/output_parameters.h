/**
 * @file output_parameters.h
 * The `Output` and `Postprocess` subsections.
 */
#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <string>
#include <vector>

namespace ausroll::io
{
  /** How much ausroll prints (`Output/Verbosity`). */
  enum class Verbosity
  {
    quiet,     ///< errors and the final summary only
    normal,    ///< one status line per load step
    verbose,   ///< plus Newton iterations
    regression ///< deterministic, low-precision lines for regression tests (no timings)
  };

  /** Parameters of subsection `Output`. */
  struct OutputParameters
  {
    std::string  directory = "output"; ///< `Directory` (relative to the working directory)
    unsigned int interval = 1;      ///< `Interval`: write VTU every this many steps (0: last only)
    bool         overwrite = false; ///< `Overwrite` earlier results in directory
    bool         write_vtu = true;  ///< `Write VTU`
    bool         deformed_mesh = false; ///< `Deformed mesh`: VTU points at deformed positions
    Verbosity    verbosity = Verbosity::normal; ///< `Verbosity`

    /** Declare subsection `Output`. */
    static void declare_parameters(dealii::ParameterHandler &prm);
    /** Read subsection `Output`. */
    void parse_parameters(dealii::ParameterHandler &prm);
  };

  /**
   * Parameters of subsection `Postprocess/Boundary profile`: the deformed shape of boundaries
   * (e.g. the rim of a rolled disk) in polar coordinates about a centre, written with every VTU
   * output as `profile_NNNN.csv` (see io::BoundaryProfile).
   */
  struct BoundaryProfileParameters
  {
    std::vector<unsigned int> boundary_ids; ///< `Boundary ids` (empty: no profile)
    dealii::Point<2>          center;       ///< `Center` of the polar angle and radius

    /** Declare subsection `Boundary profile` (inside `Postprocess`). */
    static void declare_parameters(dealii::ParameterHandler &prm);
    /** Read subsection `Boundary profile` (inside `Postprocess`). */
    void parse_parameters(dealii::ParameterHandler &prm);
  };

  /** Parameters of subsection `Postprocess`: quantities written to history.csv. */
  struct PostprocessParameters
  {
    std::string monitor_points;      ///< `Monitor points` "name: x, y; ..." -> name_ux, name_uy
    std::string reaction_boundaries; ///< `Reaction boundaries` ids -> reaction_<id>_x, _y
    std::string line_probes;         ///< `Line probes` "name: x0, y0, x1, y1, n; ..."
    std::string depth_probes;        ///< `Depth probes` "name: x, y, depth, n; ..."
    std::vector<unsigned int> depth_probe_boundaries; ///< `Depth probe boundaries` (empty: all)
    BoundaryProfileParameters boundary_profile;       ///< subsection `Boundary profile`

    /** Declare subsection `Postprocess`. */
    static void declare_parameters(dealii::ParameterHandler &prm);
    /** Read subsection `Postprocess`. */
    void parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace ausroll::io
