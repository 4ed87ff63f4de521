/**
 * @file polyline.h
 * Die shape `polyline` (subsection `Contact/Die N/Polyline`): an open chain of straight segments
 * through points given inline or in a points file; and DiePoints, the points input it shares
 * with `arc line`.
 */
#pragma once

#include <ausroll/contact/surfaces/surface_factory.h>
#include <ausroll/geometry/curve_chain.h>

#include <deal.II/base/point.h>

#include <string>
#include <vector>

namespace ausroll::contact::surfaces
{
  /**
   * The outline points of a polyline or arc-line die: `Points` inline ("x, y; x, y; ...") or
   * `Points file` (two columns x y, '#' comments, relative to the .prm file).
   */
  struct DiePoints
  {
    std::string points;      ///< `Points`
    std::string points_file; ///< `Points file` (resolved against the input directory)

    /** Declare `Points` and `Points file`; @p shape names the shape in the documentation. */
    static void declare_parameters(dealii::ParameterHandler &prm);
    /** Read them; InputError naming `<path>Points` if neither is given. */
    void parse(dealii::ParameterHandler &prm,
               const std::string        &path,
               const std::string        &input_directory);
    /** The points (at least two); InputError naming `<path>Points` or `<path>Points file`. */
    std::vector<dealii::Point<2>> read(const std::string &path) const;
  };

  /**
   * Subsection `Polyline`: an open polyline_chain() through the points in travel
   * order (die material on the right), its first and last segment extended to infinity.
   */
  struct PolylineParameters : public ShapeParameters<2>
  {
    DiePoints outline; ///< `Points`, `Points file`

    /** Declare the entries of subsection `Polyline` (the caller has entered it). */
    static void                            declare_parameters(dealii::ParameterHandler &prm);
    void                                   parse(dealii::ParameterHandler &prm,
                                                 const std::string        &path,
                                                 const std::string        &input_directory) override;
    std::unique_ptr<const RigidSurface<2>> create(const std::string &path) const override;
  };

  /**
   * Chain of straight segments through @p points (at least 2 distinct points; consecutive
   * duplicates are dropped). @p closed joins the last point to the first; @p extend_ends
   * (open chains only) extends the first and the last segment to infinity.
   */
  geometry::CurveChain polyline_chain(const std::vector<dealii::Point<2>> &points,
                                      bool                                 closed = false,
                                      bool                                 extend_ends = false);

  /**
   * Read a points file: plain text with two columns x y per line; everything after '#' is a
   * comment; blank lines are ignored. Throws ausroll::InputError (a std::runtime_error) naming
   * @p filename if the file cannot be read, a line is malformed, or it holds fewer than 2 points.
   */
  std::vector<dealii::Point<2>> read_points_file(const std::string &filename);

  /** Open polyline die from a points file (see read_points_file() and polyline_chain()). */
  geometry::CurveChain polyline_chain_from_file(const std::string &filename,
                                                bool               extend_ends = false);

} // namespace ausroll::contact::surfaces
