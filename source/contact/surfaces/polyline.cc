#include <ausroll/contact/die_surface.h>
#include <ausroll/contact/surfaces/polyline.h>
#include <ausroll/core/exceptions.h>
#include <ausroll/core/parse_utilities.h>

namespace ausroll::contact::surfaces
{
  using namespace dealii;

  void DiePoints::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Points",
                      "",
                      Patterns::Anything(),
                      "'x, y; x, y; ...' in travel order; the die material is on the right of the "
                      "direction of travel.");
    prm.declare_entry("Points file",
                      "",
                      Patterns::Anything(),
                      "Text file with two columns x y ('#' comments), relative to the .prm file; "
                      "used when Points is empty.");
  }

  void DiePoints::parse(ParameterHandler  &prm,
                        const std::string &path,
                        const std::string &input_directory)
  {
    points = prm.get("Points");
    points_file = prm.get("Points file");
    if (!points_file.empty() && points_file[0] != '/')
      points_file = input_directory + points_file;
    require(!points.empty() || !points_file.empty(),
            path + "Points",
            "give the die outline in Points or Points file");
  }

  std::vector<Point<2>> DiePoints::read(const std::string &path) const
  {
    std::vector<Point<2>> result;
    if (!points.empty())
      for (const std::string &item : split_and_trim(points, ';'))
        result.push_back(parse_point<2>(item, path + "Points"));
    else
      try
      {
        result = DieSurface::read_points_file(points_file);
      }
      catch (const std::exception &e)
      {
        throw InputError(path + "Points file: " + e.what());
      }
    require(result.size() >= 2, path + "Points", "needs at least two points");
    return result;
  }

  void PolylineParameters::declare_parameters(ParameterHandler &prm)
  {
    DiePoints::declare_parameters(prm);
  }

  void PolylineParameters::parse(ParameterHandler  &prm,
                                 const std::string &path,
                                 const std::string &input_directory)
  {
    outline.parse(prm, path, input_directory);
  }

  std::unique_ptr<const RigidSurface<2>> PolylineParameters::create(const std::string &path) const
  {
    const std::vector<Point<2>> points = outline.read(path);
    try
    {
      return std::make_unique<ChainSurface>("polyline", DieSurface::polyline(points, false, true));
    }
    catch (const std::exception &e)
    {
      throw InputError(path + "Points: " + e.what());
    }
  }
} // namespace ausroll::contact::surfaces

AUSROLL_REGISTER_DIE_SHAPE(2,
                           ausroll::contact::surfaces::PolylineParameters,
                           "polyline",
                           "Polyline",
                           "straight segments through Points, the ends extended to infinity")
