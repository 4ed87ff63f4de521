/**
 * @file arc_line.h
 * Die shape `arc line` (subsection `Contact/Die N/Arc line`): a polyline whose interior corners
 * are rounded by tangent circular arcs.
 */
#pragma once

#include <ausroll/contact/surfaces/polyline.h>

#include <vector>

namespace ausroll::contact::surfaces
{
  /**
   * Subsection `Arc line`: an arc_line_chain() through the points (as
   * `Polyline`, ends extended to infinity) with a tangent fillet of `Fillet radii` at each
   * interior corner (one value for all, or one per corner; 0 keeps a sharp corner).
   */
  struct ArcLineParameters : public ShapeParameters<2>
  {
    DiePoints           outline;      ///< `Points`, `Points file`
    std::vector<double> fillet_radii; ///< `Fillet radii` (mm)

    /** Declare the entries of subsection `Arc line` (the caller has entered it). */
    static void                            declare_parameters(dealii::ParameterHandler &prm);
    void                                   parse(dealii::ParameterHandler &prm,
                                                 const std::string        &path,
                                                 const std::string        &input_directory) override;
    std::unique_ptr<const RigidSurface<2>> create(const std::string &path) const override;
  };

  /**
   * Line-arc composite: the polygon through the corner @p points with each corner rounded by a
   * tangent circular fillet (lines and tangent arcs alternate), e.g. a punch = 3 points and one
   * fillet radius. @p fillet_radii holds one radius per corner: points.size() - 2 values for an
   * open chain (interior corners), points.size() for a closed one, or a single value for all
   * corners; a radius of 0 keeps a sharp corner. Throws ausroll::InputError if the fillets of a
   * side do not fit on it.
   */
  geometry::CurveChain arc_line_chain(const std::vector<dealii::Point<2>> &points,
                                      const std::vector<double>           &fillet_radii,
                                      bool                                 closed = false,
                                      bool                                 extend_ends = false);

} // namespace ausroll::contact::surfaces
