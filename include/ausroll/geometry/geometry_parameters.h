/**
 * @file geometry_parameters.h
 * The `Geometry` subsection: which workpiece mesh to build and how fine.
 */
#pragma once

#include <ausroll/geometry/gear_tooth_mesh.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <string>
#include <vector>

namespace ausroll::geometry
{
  /** Workpiece shape (`Geometry/Type`). */
  enum class WorkpieceType
  {
    quarter_ring, ///< quarter of an annulus (thick cylinder); subsection `Quarter ring`
    rectangle,    ///< axis-parallel rectangle (slab, block, cantilever, upsetting); `Rectangle`
    quarter_disk, ///< lower-right quarter of a disk (cylinder on a flat: Hertz); `Quarter disk`
    mesh_file,    ///< a mesh read from `Mesh file` (Gmsh .msh or UCD .inp)
    gear_tooth,   ///< involute gear tooth sector with rim; subsection `Gear tooth`
    ring          ///< full annulus (disk with a bore: disk rolling); subsection `Ring`
  };

  /**
   * Parameters of subsection `Geometry` and its shape subsections.
   */
  struct GeometryParameters
  {
    WorkpieceType type = WorkpieceType::quarter_ring; ///< `Type`
    unsigned int  global_refinements = 0;             ///< `Global refinements` of the coarse mesh
    std::string   mesh_file;                          ///< `Mesh file` (Type = mesh file)

    // subsection `Quarter ring`
    double       inner_radius = 100.; ///< `Inner radius`
    double       outer_radius = 200.; ///< `Outer radius`
    unsigned int radial_cells = 4;    ///< `Radial cells` of the coarse mesh
    unsigned int angular_cells = 4;   ///< `Angular cells` of the coarse mesh

    // subsection `Rectangle`
    dealii::Point<2>          lower_left{0., 0.};    ///< `Lower left corner`
    dealii::Point<2>          upper_right{1., 1.};   ///< `Upper right corner`
    std::vector<unsigned int> rectangle_cells{1, 1}; ///< `Cells` in x and y of the coarse mesh

    // subsection `Quarter disk`
    dealii::Point<2> disk_center{0., 1.}; ///< `Center`
    double           disk_radius = 1.;    ///< `Radius`

    // subsection `Gear tooth`
    GearToothParameters gear_tooth; ///< involute tooth sector (Type = gear tooth)
    // subsection `Ring` (full annulus; boundary ids 0 inner circle, 1 outer circle)
    dealii::Point<2> ring_center{0., 0.};     ///< `Center`
    double           ring_inner_radius = 1.;  ///< `Inner radius`
    double           ring_outer_radius = 2.;  ///< `Outer radius`
    unsigned int     ring_cells_around = 24;  ///< `Cells around` the circumference (coarse mesh)
    unsigned int     ring_cells_radially = 4; ///< `Cells radially` across the wall (coarse mesh)

    // local refinement towards a point (any shape)
    dealii::Point<2> refinement_point{0., 0.}; ///< `Refinement point`
    double           refinement_radius = 0.;   ///< `Refinement radius` (0: no local refinement)
    unsigned int     local_refinements = 0;    ///< `Local refinements` (levels)
    double           refinement_radius_factor = 0.5; ///< `Refinement radius factor` per level

    /** Declare subsection `Geometry`. */
    static void declare_parameters(dealii::ParameterHandler &prm);
    /** Read subsection `Geometry`; the mesh file path is resolved relative to @p input_directory.
     */
    void parse_parameters(dealii::ParameterHandler &prm, const std::string &input_directory);
  };
} // namespace ausroll::geometry
