#include <ausroll/contact/surfaces/chain_surface.h>
#include <ausroll/contact/surfaces/polyline.h>
#include <ausroll/core/exceptions.h>
#include <ausroll/core/input_file.h>
#include <ausroll/core/parse_utilities.h>
#include <ausroll/geometry/plane_vectors.h>

namespace ausroll::contact::surfaces
{
  using namespace dealii;
  using namespace geometry::plane;

  geometry::CurveChain
  polyline_chain(const std::vector<Point<2>> &points, const bool closed, const bool extend_ends)
  {
    require(
        !(closed && extend_ends), curve_entry, "a closed polyline cannot be extended to infinity");
    std::vector<Point<2>> p;
    for (const Point<2> &q : points)
      if (p.empty() || q.distance(p.back()) > 0.0)
        p.push_back(q);
    if (closed && p.size() > 1 && p.back().distance(p.front()) == 0.0)
      p.pop_back();
    require(p.size() >= (closed ? 3u : 2u),
            curve_entry,
            closed ? "a closed polyline needs at least 3 distinct points"
                   : "a polyline needs at least 2 distinct points");

    std::vector<geometry::CurveSegment> segments;
    const std::size_t                   n_sides = closed ? p.size() : p.size() - 1;
    for (std::size_t i = 0; i < n_sides; ++i)
    {
      const Point<2> &a = p[i], &b = p[(i + 1) % p.size()];
      const double    l = a.distance(b);
      const bool      to_first = extend_ends && i == 0, to_last = extend_ends && i + 1 == n_sides;
      if (to_first || to_last)
        segments.push_back(geometry::CurveSegment::line_through(
            a, b - a, to_first ? -inf : 0.0, to_last ? inf : l));
      else
        segments.push_back(geometry::CurveSegment::line(a, b));
    }
    geometry::CurveChain die(std::move(segments), closed);
    if (extend_ends)
      die.set_outline(p.front(), p.back());
    return die;
  }

  std::vector<Point<2>> read_points_file(const std::string &filename)
  {
    const std::string where = "Die surface points file '" + filename + "'";
    std::ifstream     in
        = open_input_file(filename, "Die surface points file", file_size_limit::points_file);
    std::vector<Point<2>> points;
    std::string           line;
    unsigned int          line_number = 0;
    while (std::getline(in, line))
    {
      ++line_number;
      const std::size_t comment = line.find('#');
      if (comment != std::string::npos)
        line.erase(comment);
      std::istringstream fields(line);
      double             x, y;
      if (!(fields >> x))
      {
        // A blank (or comment-only) line is fine; anything else is an error.
        fields.clear();
        std::string rest;
        if (fields >> rest)
          throw InputError(where + ": line " + std::to_string(line_number)
                           + " is not of the form 'x y'");
        continue;
      }
      std::string rest;
      if (!(fields >> y) || (fields >> rest))
        throw InputError(where + ": line " + std::to_string(line_number)
                         + " is not of the form 'x y'");
      points.emplace_back(x, y);
    }
    if (in.bad())
      throw InputError(where + ": read error");
    if (points.size() < 2)
      throw InputError(where + ": needs at least 2 points, found " + std::to_string(points.size()));
    return points;
  }

  geometry::CurveChain polyline_chain_from_file(const std::string &filename, const bool extend_ends)
  {
    const std::vector<Point<2>> points = read_points_file(filename);
    try
    {
      return polyline_chain(points, false, extend_ends);
    }
    catch (const InputError &e)
    {
      throw InputError("Die surface points file '" + filename + "': " + e.what());
    }
  }

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
        result = read_points_file(points_file);
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
      return std::make_unique<ChainSurface>("polyline", polyline_chain(points, false, true));
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
