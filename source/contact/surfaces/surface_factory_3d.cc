#include <ausroll/contact/surfaces/extruded_profile.h>
#include <ausroll/contact/surfaces/finite_cylinder.h>
#include <ausroll/contact/surfaces/plane.h>
#include <ausroll/contact/surfaces/revolved_profile.h>
#include <ausroll/contact/surfaces/surface_factory_3d.h>
#include <ausroll/contact/surfaces/torus.h>
#include <ausroll/core/exceptions.h>
#include <ausroll/core/parse_utilities.h>
#include <ausroll/geometry/gear_entries.h>
#include <ausroll/geometry/involute_gear.h>

#include <deal.II/base/numbers.h>

#include <cmath>
#include <limits>

namespace ausroll::contact::surfaces
{
  using namespace dealii;

  namespace
  {
    constexpr double degree = numbers::PI / 180.;

    /** Read a 3D vector entry; InputError naming @p entry. */
    Tensor<1, 3>
    get_vector(ParameterHandler &prm, const std::string &name, const std::string &entry)
    {
      return Tensor<1, 3>(parse_point<3>(prm.get(name), entry));
    }

    /** Read a nonzero 3D direction entry. */
    Tensor<1, 3>
    get_direction(ParameterHandler &prm, const std::string &name, const std::string &entry)
    {
      const Tensor<1, 3> v = get_vector(prm, name, entry);
      require(v.norm() > 0., entry, "must be a nonzero vector");
      return v;
    }

    /** Declare Center/Axis/Reference direction of an axisymmetric shape. */
    void declare_placement(ParameterHandler  &prm,
                           const std::string &center_name,
                           const std::string &center_help,
                           const std::string &axis_help,
                           const std::string &reference_help)
    {
      prm.declare_entry(center_name, "0, 0, 0", Patterns::Anything(), center_help);
      prm.declare_entry("Axis", "0, 0, 1", Patterns::Anything(), axis_help);
      prm.declare_entry("Reference direction", "1, 0, 0", Patterns::Anything(), reference_help);
    }

    /** Read Center (or Origin)/Axis/Reference direction of a shape under @p path. */
    void parse_placement(ParameterHandler  &prm,
                         const std::string &center_name,
                         const std::string &path,
                         Point<3>          &center,
                         Tensor<1, 3>      &axis,
                         Tensor<1, 3>      &reference)
    {
      center = parse_point<3>(prm.get(center_name), path + center_name);
      axis = get_direction(prm, "Axis", path + "Axis");
      reference = get_vector(prm, "Reference direction", path + "Reference direction");
    }

    /** Run a constructor; an EntryError it throws becomes an InputError under @p path. */
    template <typename Make>
    auto with_path(const std::string &path, Make make)
    {
      try
      {
        return make();
      }
      catch (const EntryError &e)
      {
        throw InputError(path + e.entry() + ": " + e.what_is_wrong());
      }
    }
  } // namespace

  // ------------------------------------------------------------------------------- Profile
  void ProfileParameters::declare_parameters(ParameterHandler  &prm,
                                             const std::string &coordinates,
                                             const bool         allow_gear)
  {
    prm.enter_subsection("Profile");
    prm.declare_entry("Type",
                      "polyline",
                      Patterns::Selection(allow_gear ? "polyline|arc line|circle|involute gear"
                                                     : "polyline|arc line|circle"),
                      "The 2D chain in coordinates (" + coordinates
                          + "); the die material lies on the right of its direction of travel.");
    prm.declare_entry("Points",
                      "",
                      Patterns::Anything(),
                      "polyline / arc line: '" + coordinates + "; " + coordinates
                          + "; ...' in travel order (mm).");
    prm.declare_entry("Points file",
                      "",
                      Patterns::Anything(),
                      "polyline / arc line: text file with two columns (" + coordinates
                          + ", '#' comments), relative to the .prm file; used when Points is "
                            "empty.");
    prm.declare_entry("Fillet radii",
                      "",
                      Patterns::Anything(),
                      "arc line: radius of the tangent arc at each corner (one value for all, or "
                      "one per corner; 0: sharp).");
    prm.declare_entry("Closed",
                      "false",
                      Patterns::Bool(),
                      "polyline / arc line: join the last point to the first.");
    prm.declare_entry("Extend ends",
                      "false",
                      Patterns::Bool(),
                      "polyline / arc line (open): extend the first and last segment to infinity.");
    prm.declare_entry(
        "Center", "0, 0", Patterns::Anything(), "circle: centre (" + coordinates + ").");
    prm.declare_entry("Radius", "1", Patterns::Double(0.), "circle: radius (mm).");
    prm.declare_entry("Material inside",
                      "true",
                      Patterns::Bool(),
                      "circle: true for material inside the circle (convex), false for a hole.");
    if (allow_gear)
    {
      prm.declare_entry("Number of teeth", "20", Patterns::Integer(3), "involute gear: teeth z.");
      prm.declare_entry("Diametral pitch",
                        "0",
                        Patterns::Double(0.),
                        "involute gear: teeth per inch of pitch diameter (0: use Module).");
      prm.declare_entry("Module", "1", Patterns::Double(0.), "involute gear: module m (mm).");
      prm.declare_entry("Pressure angle",
                        "20",
                        Patterns::Double(0., 45.),
                        "involute gear: pressure angle (degrees).");
      prm.declare_entry("Addendum",
                        "-1",
                        Patterns::Double(),
                        "involute gear: addendum (mm); negative: 1 module.");
      prm.declare_entry("Dedendum",
                        "-1",
                        Patterns::Double(),
                        "involute gear: dedendum (mm); negative: 1.25 module.");
      prm.declare_entry("Tooth thickness",
                        "-1",
                        Patterns::Double(),
                        "involute gear: tooth thickness at the pitch circle (mm); negative: half "
                        "the circular pitch.");
      prm.declare_entry("Root fillet radius",
                        "0",
                        Patterns::Double(0.),
                        "involute gear: root fillet radius (mm).");
      prm.declare_entry("Tip radius",
                        "0",
                        Patterns::Double(0.),
                        "involute gear: radius of the tip rounds (mm; 0: sharp tip corners).");
      prm.declare_entry("Tooth axis angle",
                        "0",
                        Patterns::Double(),
                        "involute gear: direction of the axis of tooth 0 (degrees from +x).");
      prm.declare_entry(
          "Teeth in sector",
          "0",
          Patterns::Integer(0),
          "involute gear: build only this many teeth around tooth 0 (0: whole gear).");
    }
    prm.leave_subsection();
  }

  void ProfileParameters::parse_parameters(ParameterHandler  &prm,
                                           const std::string &parent_path,
                                           const std::string &input_directory)
  {
    path = parent_path + "Profile/";
    prm.enter_subsection("Profile");
    const std::string t = prm.get("Type");
    type = t == "polyline"   ? Type::polyline
           : t == "arc line" ? Type::arc_line
           : t == "circle"   ? Type::circle
                             : Type::involute_gear;
    points.clear();
    for (const std::string &item : split_and_trim(prm.get("Points"), ';'))
      points.push_back(parse_point<2>(item, path + "Points"));
    points_file = prm.get("Points file");
    if (!points_file.empty() && points_file[0] != '/')
      points_file = input_directory + points_file;
    fillet_radii = parse_double_list(prm.get("Fillet radii"), path + "Fillet radii");
    for (const double r : fillet_radii)
      require(r >= 0., path + "Fillet radii", "must not be negative");
    closed = prm.get_bool("Closed");
    extend_ends = prm.get_bool("Extend ends");
    center = parse_point<2>(prm.get("Center"), path + "Center");
    radius = prm.get_double("Radius");
    material_inside = prm.get_bool("Material inside");
    if (type == Type::involute_gear)
    {
      teeth = prm.get_integer("Number of teeth");
      diametral_pitch = prm.get_double("Diametral pitch");
      module = prm.get_double("Module");
      pressure_angle = prm.get_double("Pressure angle");
      addendum = prm.get_double("Addendum");
      dedendum = prm.get_double("Dedendum");
      tooth_thickness = prm.get_double("Tooth thickness");
      root_fillet_radius = prm.get_double("Root fillet radius");
      tip_radius = prm.get_double("Tip radius");
      tooth_axis_angle = prm.get_double("Tooth axis angle");
      sector_teeth = prm.get_integer("Teeth in sector");
    }
    prm.leave_subsection();
  }

  DieSurface ProfileParameters::create() const
  {
    switch (type)
    {
      case Type::circle:
        require(radius > 0., path + "Radius", "must be positive");
        return DieSurface::circle(center, radius, material_inside);
      case Type::polyline:
      case Type::arc_line:
      {
        std::vector<Point<2>> p = points;
        if (p.empty())
        {
          require(!points_file.empty(),
                  path + "Points",
                  "needs at least two points (or a Points file)");
          try
          {
            p = DieSurface::read_points_file(points_file);
          }
          catch (const std::exception &e)
          {
            throw InputError(path + "Points file: " + e.what());
          }
        }
        require(p.size() >= 2, path + "Points", "needs at least two points");
        require(
            !(closed && extend_ends), path + "Extend ends", "is not possible for a closed chain");
        try
        {
          if (type == Type::polyline)
            return DieSurface::polyline(p, closed, extend_ends);
          require(!fillet_radii.empty(), path + "Fillet radii", "needs at least one radius");
          return DieSurface::arc_line_composite(p, fillet_radii, closed, extend_ends);
        }
        catch (const EntryError &e)
        {
          throw InputError(path + e.entry() + ": " + e.what_is_wrong());
        }
        catch (const InputError &e)
        {
          const std::string what = e.what();
          // messages that already name an entry of this subsection pass unchanged
          if (what.rfind(path, 0) == 0)
            throw;
          throw InputError(path + "Points: " + what);
        }
      }
      case Type::involute_gear:
      {
        const geometry::ToothProportions proportions
            = geometry::tooth_proportions(addendum, dedendum, tooth_thickness, root_fillet_radius);
        try
        {
          const auto gear = geometry::InvoluteGear::from_pitch_or_module(
              teeth, diametral_pitch, module, pressure_angle * degree, proportions);
          return DieSurface::involute_gear(
              gear, tooth_axis_angle * degree, sector_teeth, tip_radius);
        }
        catch (const EntryError &e)
        {
          throw InputError(path + e.entry() + ": " + e.what_is_wrong());
        }
        catch (const std::exception &e)
        {
          throw InputError(path + "Type = involute gear: invalid gear (" + std::string(e.what())
                           + ")");
        }
      }
    }
    throw InputError(path + "Type: unknown profile type");
  }

  // ------------------------------------------------------------------------------- Plane
  void PlaneParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Plane");
    prm.declare_entry("Point", "0, 0, 0", Patterns::Anything(), "A point of the plane (x, y, z).");
    prm.declare_entry("Normal",
                      "0, 0, 1",
                      Patterns::Anything(),
                      "Normal pointing out of the die, towards the workpiece (nonzero).");
    prm.declare_entry("First tangent",
                      "0, 0, 0",
                      Patterns::Anything(),
                      "Direction of the first tangent t_1 and of the first rectangle side (its "
                      "part normal to Normal; 0, 0, 0: chosen).");
    prm.declare_entry("Half length 1",
                      "0",
                      Patterns::Double(0.),
                      "Half length of the rectangle along t_1 (mm; 0: infinite).");
    prm.declare_entry("Half length 2",
                      "0",
                      Patterns::Double(0.),
                      "Half length of the rectangle along t_2 = n x t_1 (mm; 0: infinite).");
    prm.leave_subsection();
  }

  void PlaneParameters::parse_parameters(ParameterHandler &prm, const std::string &parent_path)
  {
    path = parent_path + "Plane/";
    prm.enter_subsection("Plane");
    point = parse_point<3>(prm.get("Point"), path + "Point");
    normal = get_direction(prm, "Normal", path + "Normal");
    first_tangent = get_vector(prm, "First tangent", path + "First tangent");
    half_length_1 = prm.get_double("Half length 1");
    half_length_2 = prm.get_double("Half length 2");
    prm.leave_subsection();
  }

  std::unique_ptr<RigidSurface<3>> PlaneParameters::create() const
  {
    const double inf = std::numeric_limits<double>::infinity();
    return std::make_unique<Plane>(point,
                                   normal,
                                   first_tangent,
                                   half_length_1 > 0. ? half_length_1 : inf,
                                   half_length_2 > 0. ? half_length_2 : inf);
  }

  // ------------------------------------------------------------------------------- Cylinder
  void CylinderParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Cylinder");
    declare_placement(prm,
                      "Center",
                      "Centre of the cylinder: on the axis, mid-way across the width (x, y, z).",
                      "Direction of the cylinder axis (nonzero).",
                      "Direction of theta = 0 for the surface coordinates (its part normal to "
                      "the axis).");
    prm.declare_entry("Radius", "1", Patterns::Double(0.), "Radius R (mm).");
    prm.declare_entry("Width", "1", Patterns::Double(0.), "Width w along the axis (mm).");
    prm.declare_entry("Edge radius",
                      "0",
                      Patterns::Double(0.),
                      "Radius r_e rounding the two rim edges (mm; 0: sharp; at most "
                      "min(Radius, Width / 2)).");
    prm.leave_subsection();
  }

  void CylinderParameters::parse_parameters(ParameterHandler &prm, const std::string &parent_path)
  {
    path = parent_path + "Cylinder/";
    prm.enter_subsection("Cylinder");
    parse_placement(prm, "Center", path, center, axis, reference);
    radius = prm.get_double("Radius");
    width = prm.get_double("Width");
    edge_radius = prm.get_double("Edge radius");
    prm.leave_subsection();
  }

  std::unique_ptr<RigidSurface<3>> CylinderParameters::create() const
  {
    return with_path(path,
                     [&]() -> std::unique_ptr<RigidSurface<3>> {
                       return std::make_unique<FiniteCylinder>(
                           center, axis, radius, width, edge_radius, reference);
                     });
  }

  // ------------------------------------------------------------------------------- Torus
  void TorusParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Torus");
    declare_placement(prm,
                      "Center",
                      "Centre of the torus (x, y, z).",
                      "Direction of the torus axis (the roll axis; nonzero).",
                      "Direction of theta = 0 for the surface coordinates.");
    prm.declare_entry("Major radius",
                      "2",
                      Patterns::Double(0.),
                      "R: distance from the axis to the centre of the face profile circle (mm).");
    prm.declare_entry("Minor radius",
                      "1",
                      Patterns::Double(0.),
                      "rho: radius of the face profile circle (mm), 0 < rho < R.");
    prm.leave_subsection();
  }

  void TorusParameters::parse_parameters(ParameterHandler &prm, const std::string &parent_path)
  {
    path = parent_path + "Torus/";
    prm.enter_subsection("Torus");
    parse_placement(prm, "Center", path, center, axis, reference);
    major_radius = prm.get_double("Major radius");
    minor_radius = prm.get_double("Minor radius");
    prm.leave_subsection();
  }

  std::unique_ptr<RigidSurface<3>> TorusParameters::create() const
  {
    return with_path(
        path,
        [&]() -> std::unique_ptr<RigidSurface<3>>
        { return std::make_unique<Torus>(center, axis, major_radius, minor_radius, reference); });
  }

  // ------------------------------------------------------------------------------- Revolved
  void RevolvedProfileParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Revolved profile");
    declare_placement(prm,
                      "Center",
                      "Origin of the meridian coordinates (r, z) on the axis (x, y, z).",
                      "Direction of the axis of revolution (z of the profile; nonzero).",
                      "Direction of theta = 0 for the surface coordinates.");
    ProfileParameters::declare_parameters(prm, "r, z", false);
    prm.leave_subsection();
  }

  void RevolvedProfileParameters::parse_parameters(ParameterHandler  &prm,
                                                   const std::string &parent_path,
                                                   const std::string &input_directory)
  {
    path = parent_path + "Revolved profile/";
    prm.enter_subsection("Revolved profile");
    parse_placement(prm, "Center", path, center, axis, reference);
    profile.parse_parameters(prm, path, input_directory);
    prm.leave_subsection();
  }

  std::unique_ptr<RigidSurface<3>> RevolvedProfileParameters::create() const
  {
    const DieSurface chain = profile.create();
    return with_path(path,
                     [&]() -> std::unique_ptr<RigidSurface<3>>
                     { return std::make_unique<RevolvedProfile>(chain, center, axis, reference); });
  }

  // ------------------------------------------------------------------------------- Extruded
  void ExtrudedProfileParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Extruded profile");
    declare_placement(prm,
                      "Origin",
                      "Origin of the profile coordinates (x, y, z).",
                      "Extrusion direction (z of the profile; nonzero).",
                      "Direction of the profile's x axis (its part normal to the Axis).");
    prm.declare_entry("Extent",
                      "infinite",
                      Patterns::Selection("infinite|finite|finite with caps"),
                      "infinite: unbounded along the axis; finite: z in [Start z, End z] with open "
                      "ends; finite with caps: closed by flat end faces (convex edges).");
    prm.declare_entry("Start z", "0", Patterns::Double(), "Start of the extrusion (mm).");
    prm.declare_entry("End z", "1", Patterns::Double(), "End of the extrusion (mm), > Start z.");
    ProfileParameters::declare_parameters(prm, "x, y", true);
    prm.leave_subsection();
  }

  void ExtrudedProfileParameters::parse_parameters(ParameterHandler  &prm,
                                                   const std::string &parent_path,
                                                   const std::string &input_directory)
  {
    path = parent_path + "Extruded profile/";
    prm.enter_subsection("Extruded profile");
    parse_placement(prm, "Origin", path, origin, axis, reference);
    const std::string e = prm.get("Extent");
    extent = e == "infinite" ? Extent::infinite
             : e == "finite" ? Extent::finite
                             : Extent::finite_with_caps;
    z0 = prm.get_double("Start z");
    z1 = prm.get_double("End z");
    if (extent != Extent::infinite)
      require(z1 > z0, path + "End z", "must be larger than Start z");
    profile.parse_parameters(prm, path, input_directory);
    prm.leave_subsection();
  }

  std::unique_ptr<RigidSurface<3>> ExtrudedProfileParameters::create() const
  {
    const DieSurface chain = profile.create();
    const double     inf = std::numeric_limits<double>::infinity();
    const bool       finite = extent != Extent::infinite;
    return with_path(path,
                     [&]() -> std::unique_ptr<RigidSurface<3>>
                     {
                       return std::make_unique<ExtrudedProfile>(chain,
                                                                finite ? z0 : -inf,
                                                                finite ? z1 : inf,
                                                                extent == Extent::finite_with_caps,
                                                                origin,
                                                                axis,
                                                                reference);
                     });
  }

  // ------------------------------------------------------------------------------- all
  std::string Surface3DParameters::shape_names()
  {
    return "plane|cylinder|torus|revolved profile|extruded profile";
  }

  void Surface3DParameters::declare_parameters(ParameterHandler &prm)
  {
    PlaneParameters::declare_parameters(prm);
    CylinderParameters::declare_parameters(prm);
    TorusParameters::declare_parameters(prm);
    RevolvedProfileParameters::declare_parameters(prm);
    ExtrudedProfileParameters::declare_parameters(prm);
  }

  void Surface3DParameters::parse_parameters(ParameterHandler  &prm,
                                             const std::string &parent_path,
                                             const std::string &input_directory)
  {
    plane.parse_parameters(prm, parent_path);
    cylinder.parse_parameters(prm, parent_path);
    torus.parse_parameters(prm, parent_path);
    revolved_profile.parse_parameters(prm, parent_path, input_directory);
    extruded_profile.parse_parameters(prm, parent_path, input_directory);
  }

  std::unique_ptr<RigidSurface<3>> Surface3DParameters::create(const std::string &shape) const
  {
    if (shape == "plane")
      return plane.create();
    if (shape == "cylinder")
      return cylinder.create();
    if (shape == "torus")
      return torus.create();
    if (shape == "revolved profile")
      return revolved_profile.create();
    if (shape == "extruded profile")
      return extruded_profile.create();
    throw InputError("unknown 3D surface shape '" + shape + "' (one of " + shape_names() + ")");
  }
} // namespace ausroll::contact::surfaces
