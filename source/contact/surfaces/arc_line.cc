#include <ausroll/contact/surfaces/arc_line.h>
#include <ausroll/contact/surfaces/chain_surface.h>
#include <ausroll/core/exceptions.h>
#include <ausroll/core/parse_utilities.h>
#include <ausroll/geometry/plane_vectors.h>

namespace ausroll::contact::surfaces
{
  using namespace dealii;
  using namespace geometry::plane;

  geometry::CurveChain arc_line_chain(const std::vector<Point<2>> &points,
                                      const std::vector<double>   &fillet_radii,
                                      const bool                   closed,
                                      const bool                   extend_ends)
  {
    require(!(closed && extend_ends),
            curve_entry,
            "a closed line-arc composite cannot be extended to infinity");
    const std::size_t n = points.size();
    require(n >= (closed ? 3u : 2u), curve_entry, "a line-arc composite needs more points");
    const std::size_t n_corners = closed ? n : n - 2;
    require(fillet_radii.size() == n_corners || fillet_radii.size() == 1,
            curve_entry,
            "a line-arc composite needs one fillet radius per corner (or a single one)");
    for (std::size_t i = 0; i + 1 < n + (closed ? 1 : 0); ++i)
      require(points[i].distance(points[(i + 1) % n]) > 0.0,
              curve_entry,
              "consecutive corner points of a line-arc composite must differ");

    // Corner i (at points[i]): fillet radius, turning angle, tangent length.
    struct Corner
    {
      double       radius = 0.0, turn = 0.0, tangent_length = 0.0;
      Tensor<1, 2> d_in, d_out;
    };
    std::vector<Corner> corners(n);
    for (std::size_t i = 0; i < n; ++i)
    {
      const bool interior = closed || (i > 0 && i + 1 < n);
      if (!interior)
        continue;
      Corner         &c = corners[i];
      const Point<2> &prev = points[(i + n - 1) % n], &next = points[(i + 1) % n];
      c.d_in = (points[i] - prev) / points[i].distance(prev);
      c.d_out = (next - points[i]) / next.distance(points[i]);
      c.turn = std::atan2(cross(c.d_in, c.d_out), c.d_in * c.d_out);
      c.radius = fillet_radii.size() == 1 ? fillet_radii[0] : fillet_radii[closed ? i : i - 1];
      require(c.radius >= 0.0, curve_entry, "fillet radii must not be negative");
      require(std::abs(c.turn) < M_PI * (1.0 - 1e-12) || c.radius == 0.0,
              curve_entry,
              "a fillet cannot round a corner that turns back by 180 degrees");
      if (c.radius > 0.0 && std::abs(c.turn) > 1e-12)
        c.tangent_length = c.radius * std::tan(0.5 * std::abs(c.turn));
    }
    for (std::size_t i = 0; i + 1 < n + (closed ? 1 : 0); ++i)
    {
      const std::size_t j = (i + 1) % n;
      require(corners[i].tangent_length + corners[j].tangent_length
                  <= points[i].distance(points[j]) * (1.0 + 1e-12),
              curve_entry,
              "the fillets at points " + std::to_string(i) + " and " + std::to_string(j)
                  + " do not fit on the side between them");
    }

    // Walk the corners: a straight piece up to the first tangency point, then the fillet arc.
    std::vector<geometry::CurveSegment> segments;
    const auto                          add_line = [&](const Point<2> &a, const Point<2> &b)
    {
      if (a.distance(b) > 1e-12 * a.distance(points[0]) + 1e-300)
        segments.push_back(geometry::CurveSegment::line(a, b));
    };
    const auto add_fillet = [&](const std::size_t i)
    {
      const Corner &c = corners[i];
      if (c.tangent_length == 0.0)
        return;
      const Point<2> t1 = points[i] - c.tangent_length * c.d_in;
      const double   side = c.turn > 0.0 ? 1.0 : -1.0;
      const Point<2> center = t1 + side * c.radius * rotate_left(c.d_in);
      segments.push_back(
          geometry::CurveSegment::arc(center, c.radius, polar_angle(t1 - center), c.turn));
    };
    const auto after = [&](const std::size_t i)
    { return points[i] + corners[i].tangent_length * corners[i].d_out; };
    const auto before = [&](const std::size_t i)
    { return points[i] - corners[i].tangent_length * corners[i].d_in; };

    if (closed)
    {
      for (std::size_t k = 1; k <= n; ++k)
      {
        const std::size_t i = k % n;
        add_line(after(k - 1), before(i));
        add_fillet(i);
      }
    }
    else
    {
      Point<2> start = points[0];
      for (std::size_t i = 1; i + 1 < n; ++i)
      {
        add_line(start, before(i));
        add_fillet(i);
        start = after(i);
      }
      add_line(start, points[n - 1]);
    }

    if (extend_ends)
    {
      // First and last piece become rays to infinity (inserted if the fillet consumed them).
      const Tensor<1, 2> d_first = (points[1] - points[0]) / points[1].distance(points[0]);
      const Tensor<1, 2> d_last
          = (points[n - 1] - points[n - 2]) / points[n - 1].distance(points[n - 2]);
      if (segments.front().type() == geometry::CurveSegment::Type::line
          && segments.front().start_point().distance(points[0]) == 0.0)
        segments.front() = geometry::CurveSegment::line_through(
            points[0], d_first, -inf, segments.front().u_end());
      else
        segments.insert(segments.begin(),
                        geometry::CurveSegment::line_through(points[0], d_first, -inf, 0.0));
      if (segments.size() > 1 && segments.back().type() == geometry::CurveSegment::Type::line
          && segments.back().end_point().distance(points[n - 1]) == 0.0)
        segments.back()
            = geometry::CurveSegment::line_through(segments.back().start_point(), d_last, 0.0, inf);
      else if (segments.size() == 1)
        segments.back() = geometry::CurveSegment::line_through(points[0], d_first, -inf, inf);
      else
        segments.push_back(geometry::CurveSegment::line_through(points[n - 1], d_last, 0.0, inf));
    }
    geometry::CurveChain die(std::move(segments), closed);
    if (extend_ends)
      die.set_outline(points[0], points[n - 1]);
    return die;
  }

  void ArcLineParameters::declare_parameters(ParameterHandler &prm)
  {
    DiePoints::declare_parameters(prm);
    prm.declare_entry("Fillet radii",
                      "",
                      Patterns::Anything(),
                      "Radius of the tangent arc at each interior corner (one value for all, or "
                      "one per corner; mm).");
  }

  void ArcLineParameters::parse(ParameterHandler  &prm,
                                const std::string &path,
                                const std::string &input_directory)
  {
    outline.parse(prm, path, input_directory);
    fillet_radii = parse_double_list(prm.get("Fillet radii"), path + "Fillet radii");
    require(!fillet_radii.empty(), path + "Fillet radii", "needs at least one radius");
  }

  std::unique_ptr<const RigidSurface<2>> ArcLineParameters::create(const std::string &path) const
  {
    const std::vector<Point<2>> points = outline.read(path);
    try
    {
      return std::make_unique<ChainSurface>("arc line",
                                            arc_line_chain(points, fillet_radii, false, true));
    }
    catch (const std::exception &e)
    {
      throw InputError(path + "Points: " + e.what());
    }
  }
} // namespace ausroll::contact::surfaces

AUSROLL_REGISTER_DIE_SHAPE(2,
                           ausroll::contact::surfaces::ArcLineParameters,
                           "arc line",
                           "Arc line",
                           "a polyline with tangent fillet arcs at its corners")
