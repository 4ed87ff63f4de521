#include <ausroll/core/exceptions.h>
#include <ausroll/core/parse_utilities.h>
#include <ausroll/geometry/geometry_parameters.h>

namespace ausroll::geometry
{
  using namespace dealii;

  namespace
  {
    /** The `Geometry/Type` value of @p type. */
    std::string type_name(const WorkpieceType type)
    {
      switch (type)
      {
        case WorkpieceType::quarter_ring:
          return "quarter ring";
        case WorkpieceType::rectangle:
          return "rectangle";
        case WorkpieceType::quarter_disk:
          return "quarter disk";
        case WorkpieceType::mesh_file:
          return "mesh file";
        case WorkpieceType::gear_tooth:
          return "gear tooth";
        case WorkpieceType::ring:
          return "ring";
        case WorkpieceType::block:
          return "block";
        case WorkpieceType::quarter_cylinder:
          return "quarter cylinder";
        case WorkpieceType::thick_ring:
          return "thick ring";
        case WorkpieceType::extruded_gear_tooth:
          return "extruded gear tooth";
      }
      return "?";
    }
  } // namespace

  void GeometryParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    prm.declare_entry(
        "Type",
        "quarter ring",
        Patterns::Selection("quarter ring|rectangle|quarter disk|mesh file|gear tooth|ring|"
                            "block|quarter cylinder|thick ring|extruded gear tooth"),
        "Workpiece shape. 2D shapes and their boundary ids: quarter ring: 0 inner arc, 1 outer "
        "arc, 2 edge on the x axis, 3 edge on the y axis; rectangle: 0 left, 1 right, "
        "2 bottom, 3 top; quarter disk (the quarter below and right of the centre): "
        "0 arc, 1 top edge, 2 edge on the vertical axis; gear tooth: 0 tooth outline, 1 inner "
        "arc, 2 side cuts; ring (full annulus): 0 inner circle, 1 outer circle (a sector: 2 cut "
        "at angle 0, 3 cut at the Sector angle). 3D shapes: "
        "block: 0 x = x_min, 1 x = x_max, 2 y = y_min, 3 y = y_max, 4 z = z_min, 5 z = z_max "
        "(with the lower corner at the origin 0, 2, 4 are the symmetry planes x = 0, y = 0, "
        "z = 0); quarter cylinder (x >= 0, y >= 0, axis z): 0 symmetry plane x = 0, 1 symmetry "
        "plane y = 0, 2 mantle, 3 end z = 0, 4 end z = Length; thick ring (the Ring annulus, "
        "upper half z >= 0 of the thickness): 0 bore, 1 rim, 2 side face z = Thickness/2, "
        "3 symmetry face z = 0 (a sector: 4 cut at angle 0, 5 cut at the "
        "Sector angle); extruded gear tooth (the Gear tooth sector, upper half z >= 0 "
        "of the face width): 0 tooth outline, 1 inner arc, 2 side cuts (as in 2D), 3 face end "
        "z = Face width/2, 4 symmetry face z = 0. mesh file: the ids stored in the file (2D or "
        "3D).");
    prm.declare_entry("Global refinements",
                      "0",
                      Patterns::Integer(0, 12),
                      "Uniform refinements of the coarse mesh before the run starts.");
    prm.declare_entry(
        "Mesh file",
        "",
        Patterns::Anything(),
        "Mesh for Type = mesh file, relative to the .prm file: Gmsh .msh (physical tags as "
        "boundary ids), Abaqus .inp (surfaces as boundary ids, element sets as material ids: the "
        "number in the name, e.g. *Surface, name=SS2 is boundary 2; see the manual) or UCD "
        ".ucd.");

    prm.declare_entry("Refinement point",
                      "0, 0",
                      Patterns::Anything(),
                      "Centre of local refinement (e.g. the first contact point).");
    prm.declare_entry(
        "Refinement radius",
        "0",
        Patterns::Double(0.),
        "Cells within this distance of the Refinement point are refined; the radius "
        "shrinks by the Refinement radius factor with every level (0: no local refinement).");
    prm.declare_entry(
        "Refinement radius factor",
        "0.5",
        Patterns::Double(0.05, 1.),
        "The refinement radius is multiplied by this factor from one level to the next.");
    prm.declare_entry(
        "Local refinements",
        "0",
        Patterns::Integer(0, 20),
        "Levels of local refinement towards the Refinement point (after the global ones).");

    prm.enter_subsection("Quarter disk");
    prm.declare_entry("Center", "0, 1", Patterns::Anything(), "Centre of the disk (mm).");
    prm.declare_entry("Radius", "1", Patterns::Double(0.), "Radius of the disk (mm).");
    prm.leave_subsection();

    prm.enter_subsection("Quarter ring");
    prm.declare_entry("Inner radius", "100", Patterns::Double(0.), "Inner radius a (mm).");
    prm.declare_entry("Outer radius", "200", Patterns::Double(0.), "Outer radius b (mm).");
    prm.declare_entry("Radial cells", "4", Patterns::Integer(1), "Coarse cells across the wall.");
    prm.declare_entry(
        "Angular cells", "4", Patterns::Integer(1), "Coarse cells along the quarter.");
    prm.leave_subsection();

    GearToothParameters::declare_parameters(prm);
    prm.enter_subsection("Ring");
    prm.declare_entry("Center", "0, 0", Patterns::Anything(), "Centre of the annulus (mm).");
    prm.declare_entry("Inner radius", "1", Patterns::Double(), "Bore radius (mm), > 0.");
    prm.declare_entry(
        "Outer radius", "2", Patterns::Double(), "Outer radius (mm), > Inner radius.");
    prm.declare_entry("Cells around",
                      "24",
                      Patterns::Integer(3),
                      "Coarse cells along the circumference (24: 15 degree spacing).");
    prm.declare_entry("Cells radially", "4", Patterns::Integer(1), "Coarse cells across the wall.");
    prm.declare_entry(
        "Sector angle",
        "360",
        Patterns::Double(0., 360.),
        "360: the full annulus; less: the sector 0 <= angle <= Sector angle "
        "(degrees, counter-clockwise from +x about Center; Cells around then spans "
        "the sector) with its cut edges as symmetry boundaries: ids 2 (angle 0) and 3 "
        "(Sector angle) in 2D, 4 and 5 for Type = thick ring.");
    prm.leave_subsection();

    prm.enter_subsection("Block");
    prm.declare_entry("Lower corner",
                      "0, 0, 0",
                      Patterns::List(Patterns::Double(), 3, 3),
                      "x, y, z (mm); at the origin the faces x = 0, y = 0, z = 0 (ids 0, 2, 4) "
                      "can be symmetry planes.");
    prm.declare_entry(
        "Upper corner", "1, 1, 1", Patterns::List(Patterns::Double(), 3, 3), "x, y, z (mm).");
    prm.declare_entry("Cells",
                      "1, 1, 1",
                      Patterns::List(Patterns::Integer(1), 3, 3),
                      "Coarse cells in x, y and z.");
    prm.leave_subsection();

    prm.enter_subsection("Quarter cylinder");
    prm.declare_entry("Radius", "1", Patterns::Double(), "Radius (mm), > 0; axis: the z axis.");
    prm.declare_entry("Length", "1", Patterns::Double(), "Length along z (mm), > 0.");
    prm.declare_entry("Layers",
                      "2",
                      Patterns::Integer(1, 1000),
                      "Coarse cells along the axis (the cross-section has 3 coarse cells).");
    prm.leave_subsection();

    prm.enter_subsection("Thick ring");
    prm.declare_entry("Thickness",
                      "1",
                      Patterns::Double(),
                      "Whole thickness (mm), > 0; the mesh is the upper half 0 <= z <= "
                      "Thickness/2 of the annulus of subsection Ring (centre, radii, cells).");
    prm.declare_entry(
        "Layers", "2", Patterns::Integer(1, 1000), "Coarse cells through the half thickness.");
    prm.leave_subsection();

    prm.enter_subsection("Extruded gear tooth");
    prm.declare_entry("Face width",
                      "10",
                      Patterns::Double(),
                      "Whole face width (mm), > 0; the mesh is the upper half 0 <= z <= Face "
                      "width/2 of the tooth sector of subsection Gear tooth.");
    prm.declare_entry(
        "Layers", "2", Patterns::Integer(1, 1000), "Coarse cells through the half face width.");
    prm.declare_entry("Layer ratio",
                      "1",
                      Patterns::Double(),
                      "Thickness of the coarse layer at the face end over that of the layer at "
                      "the symmetry face (> 0; geometric progression; < 1 grades the mesh towards "
                      "the face end, 1 uniform layers).");
    prm.leave_subsection();

    prm.enter_subsection("Rectangle");
    prm.declare_entry(
        "Lower left corner", "0, 0", Patterns::List(Patterns::Double(), 2, 2), "x, y (mm).");
    prm.declare_entry(
        "Upper right corner", "1, 1", Patterns::List(Patterns::Double(), 2, 2), "x, y (mm).");
    prm.declare_entry(
        "Cells", "1, 1", Patterns::List(Patterns::Integer(1), 2, 2), "Coarse cells in x and y.");
    prm.leave_subsection();
    prm.leave_subsection();
  }

  void GeometryParameters::parse_parameters(ParameterHandler  &prm,
                                            const std::string &input_directory)
  {
    prm.enter_subsection("Geometry");
    const std::string t = prm.get("Type");
    type = t == "quarter ring"          ? WorkpieceType::quarter_ring
           : t == "rectangle"           ? WorkpieceType::rectangle
           : t == "quarter disk"        ? WorkpieceType::quarter_disk
           : t == "gear tooth"          ? WorkpieceType::gear_tooth
           : t == "ring"                ? WorkpieceType::ring
           : t == "block"               ? WorkpieceType::block
           : t == "quarter cylinder"    ? WorkpieceType::quarter_cylinder
           : t == "thick ring"          ? WorkpieceType::thick_ring
           : t == "extruded gear tooth" ? WorkpieceType::extruded_gear_tooth
                                        : WorkpieceType::mesh_file;
    refinement_point = parse_point<2>(prm.get("Refinement point"), "Geometry/Refinement point");
    refinement_radius = prm.get_double("Refinement radius");
    local_refinements = prm.get_integer("Local refinements");
    refinement_radius_factor = prm.get_double("Refinement radius factor");
    prm.enter_subsection("Quarter disk");
    disk_center = parse_point<2>(prm.get("Center"), "Geometry/Quarter disk/Center");
    disk_radius = prm.get_double("Radius");
    prm.leave_subsection();
    global_refinements = prm.get_integer("Global refinements");
    mesh_file = prm.get("Mesh file");
    if (!mesh_file.empty() && mesh_file[0] != '/')
      mesh_file = input_directory + mesh_file;

    prm.enter_subsection("Quarter ring");
    inner_radius = prm.get_double("Inner radius");
    outer_radius = prm.get_double("Outer radius");
    radial_cells = prm.get_integer("Radial cells");
    angular_cells = prm.get_integer("Angular cells");
    prm.leave_subsection();

    gear_tooth.parse_parameters(prm);
    prm.enter_subsection("Ring");
    ring_center = parse_point<2>(prm.get("Center"), "Geometry/Ring/Center");
    ring_inner_radius = prm.get_double("Inner radius");
    ring_outer_radius = prm.get_double("Outer radius");
    ring_cells_around = prm.get_integer("Cells around");
    ring_cells_radially = prm.get_integer("Cells radially");
    ring_sector_angle = prm.get_double("Sector angle");
    prm.leave_subsection();

    prm.enter_subsection("Rectangle");
    lower_left
        = parse_point<2>(prm.get("Lower left corner"), "Geometry/Rectangle/Lower left corner");
    upper_right
        = parse_point<2>(prm.get("Upper right corner"), "Geometry/Rectangle/Upper right corner");
    rectangle_cells = parse_unsigned_list(prm.get("Cells"), "Geometry/Rectangle/Cells");
    prm.leave_subsection();

    prm.enter_subsection("Block");
    block_lower = parse_point<3>(prm.get("Lower corner"), "Geometry/Block/Lower corner");
    block_upper = parse_point<3>(prm.get("Upper corner"), "Geometry/Block/Upper corner");
    block_cells = parse_unsigned_list(prm.get("Cells"), "Geometry/Block/Cells");
    prm.leave_subsection();
    prm.enter_subsection("Quarter cylinder");
    cylinder_radius = prm.get_double("Radius");
    cylinder_length = prm.get_double("Length");
    cylinder_layers = prm.get_integer("Layers");
    prm.leave_subsection();
    prm.enter_subsection("Thick ring");
    ring_thickness = prm.get_double("Thickness");
    ring_layers = prm.get_integer("Layers");
    prm.leave_subsection();
    prm.enter_subsection("Extruded gear tooth");
    gear_face_width = prm.get_double("Face width");
    gear_layers = prm.get_integer("Layers");
    gear_layer_ratio = prm.get_double("Layer ratio");
    prm.leave_subsection();
    prm.leave_subsection();

    if (type == WorkpieceType::quarter_ring)
      require(inner_radius > 0. && inner_radius < outer_radius,
              "Geometry/Quarter ring/Inner radius",
              "must be positive and smaller than Outer radius");
    if (type == WorkpieceType::ring || type == WorkpieceType::thick_ring)
    {
      require(ring_inner_radius > 0., "Geometry/Ring/Inner radius", "must be positive");
      require(ring_outer_radius > ring_inner_radius,
              "Geometry/Ring/Outer radius",
              "must be larger than Inner radius");
      require(ring_sector_angle > 0., "Geometry/Ring/Sector angle", "must be positive");
    }
    if (type == WorkpieceType::rectangle)
      require(lower_left[0] < upper_right[0] && lower_left[1] < upper_right[1],
              "Geometry/Rectangle/Upper right corner",
              "must lie above and right of Lower left corner");
    if (type == WorkpieceType::mesh_file)
      require(!mesh_file.empty(), "Geometry/Mesh file", "must be set when Type = mesh file");
    if (type == WorkpieceType::gear_tooth || type == WorkpieceType::extruded_gear_tooth)
      gear_tooth.inner_radius(); // builds the gear: throws for inconsistent Gear tooth entries
    if (type == WorkpieceType::block)
      for (unsigned int d = 0; d < 3; ++d)
        require(block_lower[d] < block_upper[d],
                "Geometry/Block/Upper corner",
                "must be larger than Lower corner in x, y and z");
    if (type == WorkpieceType::quarter_cylinder)
    {
      require(cylinder_radius > 0., "Geometry/Quarter cylinder/Radius", "must be positive");
      require(cylinder_length > 0., "Geometry/Quarter cylinder/Length", "must be positive");
    }
    if (type == WorkpieceType::thick_ring)
      require(ring_thickness > 0., "Geometry/Thick ring/Thickness", "must be positive");
    if (type == WorkpieceType::extruded_gear_tooth)
    {
      require(gear_face_width > 0., "Geometry/Extruded gear tooth/Face width", "must be positive");
      require(
          gear_layer_ratio > 0., "Geometry/Extruded gear tooth/Layer ratio", "must be positive");
    }
  }

  unsigned int GeometryParameters::dimension() const
  {
    switch (type)
    {
      case WorkpieceType::block:
      case WorkpieceType::quarter_cylinder:
      case WorkpieceType::thick_ring:
      case WorkpieceType::extruded_gear_tooth:
        return 3;
      case WorkpieceType::mesh_file:
        return 0;
      default:
        return 2;
    }
  }

  void GeometryParameters::require_dimension(const unsigned int dim) const
  {
    const unsigned int d = dimension();
    if (d != 0 && d != dim)
      throw InputError("Geometry/Type: '" + type_name(type) + "' is "
                       + (d == 3 ? "three-dimensional (block, quarter cylinder, thick ring, "
                                   "extruded gear tooth)"
                                 : "two-dimensional (quarter ring, rectangle, quarter disk, gear "
                                   "tooth, ring)")
                       + ", but the run is " + std::to_string(dim) + "D: choose a "
                       + std::to_string(dim) + "D shape");
  }
} // namespace ausroll::geometry
