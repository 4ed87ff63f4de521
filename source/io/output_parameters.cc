#include <ausroll/core/exceptions.h>
#include <ausroll/core/parse_utilities.h>
#include <ausroll/io/output_parameters.h>

namespace ausroll::io
{
  using namespace dealii;

  void OutputParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    prm.declare_entry(
        "Directory",
        "output",
        Patterns::Anything(),
        "Directory for solution.pvd, the VTU files and history.csv (created if missing).");
    prm.declare_entry("Interval",
                      "1",
                      Patterns::Integer(0),
                      "Write VTU output every this many load steps (0: only the last step).");
    prm.declare_entry("Overwrite",
                      "false",
                      Patterns::Bool(),
                      "A new run into a Directory that holds results of an earlier run "
                      "(history.csv, solution.pvd, numbered outputs, checkpoint) is refused unless "
                      "this is true or 'ausroll FILE.prm --overwrite' is used; then those earlier "
                      "results are deleted (other files are left alone).");
    prm.declare_entry(
        "Write VTU", "true", Patterns::Bool(), "Write VTU/PVTU files and solution.pvd.");
    prm.declare_entry("Deformed mesh",
                      "false",
                      Patterns::Bool(),
                      "Place VTU points at their deformed positions (otherwise use ParaView's "
                      "'Warp By Vector' with the displacement field).");
    prm.declare_entry("Verbosity",
                      "normal",
                      Patterns::Selection("quiet|normal|verbose|regression"),
                      "quiet: errors and summary; normal: a status line per step; verbose: plus "
                      "Newton iterations; regression: deterministic lines for tests.");
    prm.leave_subsection();
  }

  void OutputParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    directory = prm.get("Directory");
    interval = prm.get_integer("Interval");
    overwrite = prm.get_bool("Overwrite");
    write_vtu = prm.get_bool("Write VTU");
    deformed_mesh = prm.get_bool("Deformed mesh");
    const std::string v = prm.get("Verbosity");
    verbosity = v == "quiet"     ? Verbosity::quiet
                : v == "normal"  ? Verbosity::normal
                : v == "verbose" ? Verbosity::verbose
                                 : Verbosity::regression;
    prm.leave_subsection();
    require(!directory.empty(), "Output/Directory", "must not be empty");
  }

  void PostprocessParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Postprocess");
    prm.declare_entry("Monitor points",
                      "",
                      Patterns::Anything(),
                      "Points whose displacement goes to history.csv, as 'name: x, y; name2: x, y' "
                      "(reference coordinates); columns name_ux, name_uy.");
    prm.declare_entry("Reaction boundaries",
                      "",
                      Patterns::List(Patterns::Integer(0, 255)),
                      "Boundary ids whose total reaction force goes to history.csv "
                      "(columns reaction_<id>_x, reaction_<id>_y; axisymmetric: full 2 pi).");
    prm.declare_entry(
        "Line probes",
        "",
        Patterns::Anything(),
        "Straight lines 'name: x0, y0, x1, y1, n; ...' (reference coordinates, n points) "
        "along which displacement, stress, strain and plastic strain (thermal scenes: also "
        "temperature, martensite and bainite fractions, carbon content) are written to "
        "probe_<name>_NNNN.csv at every VTU output.");
    prm.declare_entry(
        "Depth probes",
        "",
        Patterns::Anything(),
        "Lines normal to the initial surface 'name: x, y, depth, n; ...' (3D: x, y, z): each "
        "starts at the point of the workpiece's initial outline (the boundaries of Depth probe "
        "boundaries) nearest to (x, y), runs along the inward normal there for depth mm, and "
        "has n points. Written to depth_<name>_NNNN.csv at every VTU output with the columns "
        "of a line probe (s = depth below the initial surface) and the stress in the frame of "
        "the surface: stress_nn (normal), stress_tt (tangential in the section; 3D: in the "
        "x-y plane), stress_nt (2D; 3D: also stress_ww, stress_nw, stress_tw, w = n x t). For "
        "residual stress depth profiles below a flank or a rim.");
    prm.declare_entry("Depth probe boundaries",
                      "",
                      Patterns::List(Patterns::Integer(0, 255)),
                      "Boundary ids whose faces form the outline of the Depth probes (empty: "
                      "every boundary of the workpiece).");
    BoundaryProfileParameters::declare_parameters(prm);
    prm.leave_subsection();
  }

  void PostprocessParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Postprocess");
    monitor_points = prm.get("Monitor points");
    reaction_boundaries = prm.get("Reaction boundaries");
    line_probes = prm.get("Line probes");
    depth_probes = prm.get("Depth probes");
    depth_probe_boundaries.clear();
    for (const std::string &id : Utilities::split_string_list(prm.get("Depth probe boundaries")))
      depth_probe_boundaries.push_back(Utilities::string_to_int(id));
    boundary_profile.parse_parameters(prm);
    prm.leave_subsection();
  }

  void BoundaryProfileParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Boundary profile");
    prm.declare_entry("Boundary ids",
                      "",
                      Patterns::List(Patterns::Integer(0, 255)),
                      "Boundaries whose nodes are written, sorted by polar angle about the Center, "
                      "to profile_NNNN.csv at every VTU output (reference and current position, "
                      "angle, current radius, radial displacement). Empty: no profile.");
    prm.declare_entry("Center",
                      "0, 0",
                      Patterns::Anything(),
                      "Origin of the polar angle and radius (mm), e.g. the disk centre.");
    prm.leave_subsection();
  }

  void BoundaryProfileParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Boundary profile");
    boundary_ids
        = parse_unsigned_list(prm.get("Boundary ids"), "Postprocess/Boundary profile/Boundary ids");
    center = parse_point<2>(prm.get("Center"), "Postprocess/Boundary profile/Center");
    prm.leave_subsection();
  }
} // namespace ausroll::io
