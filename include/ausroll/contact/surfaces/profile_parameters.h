/**
 * @file profile_parameters.h
 * Subsection `Profile` of the 3D die shapes `Revolved profile` and `Extruded profile`: the 2D
 * chain they revolve or extrude.
 */
#pragma once

#include <ausroll/contact/surfaces/surface_factory.h>
#include <ausroll/geometry/curve_chain.h>

#include <deal.II/base/parameter_handler.h>

#include <memory>
#include <string>

namespace ausroll::contact::surfaces
{
  /**
   * The 2D chain of a revolved or extruded profile (subsection `Profile`): any registered 2D die
   * shape (`Type`, its entries in its own subsection `Profile/<Shape>`, the same subsection as
   * under `Contact/Die N`) that is a chain of segments (flat, polyline, arc line, circle,
   * involute gear; not the ellipse). `Closed` and `Extend ends` shape the chains given by points
   * (polyline, arc line), which as 2D dies are open with their ends extended.
   */
  struct ProfileParameters
  {
    std::string type = "polyline"; ///< `Type`: a registered 2D shape
    /** The entries of the shape's subsection `Profile/<Shape>`. */
    std::shared_ptr<const ShapeParameters<2>> shape;
    bool                                      closed = false;      ///< `Closed`
    bool                                      extend_ends = false; ///< `Extend ends`
    std::string path; ///< full path of the subsection (set by parse_parameters())

    /**
     * Declare subsection `Profile`; @p coordinates names the 2D coordinates for the help texts
     * ("r, z" or "x, y").
     */
    static void declare_parameters(dealii::ParameterHandler &prm, const std::string &coordinates);
    /** Read subsection `Profile`; @p parent_path is the enclosing path ("…/Revolved profile/"). */
    void parse_parameters(dealii::ParameterHandler &prm,
                          const std::string        &parent_path,
                          const std::string        &input_directory);
    /** Build the chain; InputError naming the entry if it cannot be built. */
    geometry::CurveChain create() const;
  };

} // namespace ausroll::contact::surfaces
