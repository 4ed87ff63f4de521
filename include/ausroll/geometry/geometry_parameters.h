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
    ring,         ///< full annulus (disk with a bore: disk rolling); subsection `Ring`
    // three-dimensional workpieces (dim = 3 only)
    block,            ///< axis-parallel box; subsection `Block`
    quarter_cylinder, ///< quarter of a cylinder about the z axis; subsection `Quarter cylinder`
    thick_ring, ///< upper half (z >= 0) of a ring of a thickness: the `Ring` annulus extruded;
                ///< subsection `Thick ring`
    extruded_gear_tooth ///< upper half (z >= 0) of the face width: the `Gear tooth` sector
                        ///< extruded; subsection `Extruded gear tooth`
  };

  /** Boundary ids of the three-dimensional workpieces (documented in `Geometry/Type`). */
  namespace boundary_ids_3d
  {
    /** Block: faces x = x_min, x_max, y = y_min, y_max, z = z_min, z_max. */
    namespace block
    {
      constexpr unsigned int x_min = 0, x_max = 1, y_min = 2, y_max = 3, z_min = 4, z_max = 5;
    } // namespace block
    /** Quarter cylinder: symmetry planes x = 0 and y = 0, mantle, ends z = 0 and z = Length. */
    namespace quarter_cylinder
    {
      constexpr unsigned int symmetry_x = 0, symmetry_y = 1, mantle = 2, bottom = 3, top = 4;
    } // namespace quarter_cylinder
    /** Thick ring: bore, rim, side face z = Thickness / 2, symmetry face z = 0; a sector
        (`Ring/Sector angle` < 360) also has its cut faces at angle 0 and at the sector angle. */
    namespace thick_ring
    {
      constexpr unsigned int bore = 0, rim = 1, side = 2, symmetry = 3, cut_start = 4, cut_end = 5;
    } // namespace thick_ring
    /** Extruded gear tooth: the 2D ids 0 outline, 1 inner arc, 2 side cuts on the lateral faces;
        3 face end z = Face width / 2, 4 symmetry face z = 0. */
    namespace extruded_gear_tooth
    {
      constexpr unsigned int outline = 0, inner_arc = 1, side_cuts = 2, face_end = 3, symmetry = 4;
    } // namespace extruded_gear_tooth
  }   // namespace boundary_ids_3d

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
    dealii::Point<2> ring_center{0., 0.};      ///< `Center`
    double           ring_inner_radius = 1.;   ///< `Inner radius`
    double           ring_outer_radius = 2.;   ///< `Outer radius`
    unsigned int     ring_cells_around = 24;   ///< `Cells around` the circumference (coarse mesh)
    unsigned int     ring_cells_radially = 4;  ///< `Cells radially` across the wall (coarse mesh)
    double           ring_sector_angle = 360.; ///< `Sector angle` (degrees; 360: full annulus)

    // subsection `Block` (dim = 3)
    dealii::Point<3>          block_lower{0., 0., 0.}; ///< `Lower corner`
    dealii::Point<3>          block_upper{1., 1., 1.}; ///< `Upper corner`
    std::vector<unsigned int> block_cells{1, 1, 1};    ///< `Cells` in x, y, z (coarse mesh)

    // subsection `Quarter cylinder` (dim = 3; x >= 0, y >= 0, 0 <= z <= Length)
    double       cylinder_radius = 1.; ///< `Radius`
    double       cylinder_length = 1.; ///< `Length` along the z axis
    unsigned int cylinder_layers = 2;  ///< `Layers` of coarse cells along the axis

    // subsection `Thick ring` (dim = 3; cross-section from subsection `Ring`)
    double       ring_thickness = 1.; ///< `Thickness` (whole ring; the mesh is its half z >= 0)
    unsigned int ring_layers = 2;     ///< `Layers` of coarse cells through the half thickness

    // subsection `Extruded gear tooth` (dim = 3; cross-section from subsection `Gear tooth`)
    double       gear_face_width = 10.; ///< `Face width` (whole; the mesh is its half z >= 0)
    unsigned int gear_layers = 2;       ///< `Layers` of coarse cells through the half face width
    double gear_layer_ratio = 1.; ///< `Layer ratio`: last (face end) over first layer thickness

    // local refinement towards a point (any shape)
    dealii::Point<2> refinement_point{0., 0.}; ///< `Refinement point`
    double           refinement_radius = 0.;   ///< `Refinement radius` (0: no local refinement)
    unsigned int     local_refinements = 0;    ///< `Local refinements` (levels)
    double           refinement_radius_factor = 0.5; ///< `Refinement radius factor` per level

    /**
     * Space dimension the `Type` builds: 2 for the planar shapes, 3 for block, quarter cylinder,
     * thick ring and extruded gear tooth, 0 for a mesh file (either).
     */
    unsigned int dimension() const;

    /**
     * InputError naming `Geometry/Type` unless the shape can be built in @p dim dimensions (a 3D
     * shape in a 2D run or a 2D shape in a 3D run).
     */
    void require_dimension(unsigned int dim) const;

    /** Declare subsection `Geometry`. */
    static void declare_parameters(dealii::ParameterHandler &prm);
    /** Read subsection `Geometry`; the mesh file path is resolved relative to @p input_directory.
     */
    void parse_parameters(dealii::ParameterHandler &prm, const std::string &input_directory);
  };
} // namespace ausroll::geometry
