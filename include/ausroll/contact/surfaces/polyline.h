/**
 * @file polyline.h
 * Die shape `polyline` (subsection `Contact/Die N/Polyline`): an open chain of straight segments
 * through points given inline or in a points file; and DiePoints, the points input it shares
 * with `arc line`.
 */
#pragma once

#include <ausroll/contact/surfaces/surface_factory.h>

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
   * Subsection `Polyline`: an open DieSurface::polyline() chain through the points in travel
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
} // namespace ausroll::contact::surfaces
