#include <ausroll/contact/surfaces/arc_line.h>
#include <ausroll/contact/surfaces/chain_surface.h>
#include <ausroll/contact/surfaces/polyline.h>
#include <ausroll/contact/surfaces/profile_parameters.h>
#include <ausroll/core/exceptions.h>

#include <vector>

namespace ausroll::contact::surfaces
{
  using namespace dealii;

  void ProfileParameters::declare_parameters(ParameterHandler &prm, const std::string &coordinates)
  {
    const auto &shapes = ShapeRegistry<2>::instance();
    prm.enter_subsection("Profile");
    prm.declare_entry("Type",
                      "polyline",
                      Patterns::Selection(shapes.selection()),
                      "The 2D chain in coordinates (" + coordinates
                          + "): a 2D die shape, its entries in the subsection of the same name "
                            "(Polyline, Arc line, Circle, Involute gear, Flat; not an ellipse); "
                            "the die material lies on the right of its direction of travel.");
    prm.declare_entry("Closed",
                      "false",
                      Patterns::Bool(),
                      "polyline / arc line: join the last point to the first.");
    prm.declare_entry("Extend ends",
                      "false",
                      Patterns::Bool(),
                      "polyline / arc line (open): extend the first and last segment to infinity.");
    shapes.declare_subsections(prm);
    prm.leave_subsection();
  }

  void ProfileParameters::parse_parameters(ParameterHandler  &prm,
                                           const std::string &parent_path,
                                           const std::string &input_directory)
  {
    path = parent_path + "Profile/";
    prm.enter_subsection("Profile");
    type = prm.get("Type");
    closed = prm.get_bool("Closed");
    extend_ends = prm.get_bool("Extend ends");
    shape = ShapeRegistry<2>::instance().parse(type, prm, path, input_directory, "Type");
    prm.leave_subsection();
  }

  geometry::CurveChain ProfileParameters::create() const
  {
    const std::string shape_path = ShapeRegistry<2>::instance().path(type, path);
    const auto *const polyline = dynamic_cast<const PolylineParameters *>(shape.get());
    const auto *const arc_line = dynamic_cast<const ArcLineParameters *>(shape.get());
    if (polyline != nullptr || arc_line != nullptr)
    {
      // the chains given by points: open or closed, ends extended or not
      const std::vector<Point<2>> points = polyline != nullptr ? polyline->outline.read(shape_path)
                                                               : arc_line->outline.read(shape_path);
      require(!(closed && extend_ends), path + "Extend ends", "is not possible for a closed chain");
      try
      {
        if (polyline != nullptr)
          return polyline_chain(points, closed, extend_ends);
        return arc_line_chain(points, arc_line->fillet_radii, closed, extend_ends);
      }
      catch (const EntryError &e)
      {
        throw InputError(shape_path + e.entry() + ": " + e.what_is_wrong());
      }
      catch (const InputError &e)
      {
        const std::string what = e.what();
        // messages that already name an entry of this subsection pass unchanged
        if (what.rfind(path, 0) == 0)
          throw;
        throw InputError(shape_path + "Points: " + what);
      }
    }
    const std::unique_ptr<const RigidSurface<2>> surface = shape->create(shape_path);
    if (const auto *chain = dynamic_cast<const ChainSurface *>(surface.get()))
      return chain->chain();
    throw InputError(path + "Type: '" + type
                     + "' is no chain of segments; a profile needs a polyline, arc line, circle, "
                       "involute gear or flat");
  }
} // namespace ausroll::contact::surfaces
