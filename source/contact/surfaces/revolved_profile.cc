#include <ausroll/contact/surfaces/revolved_profile.h>
#include <ausroll/contact/surfaces/shape_entries_3d.h>
#include <ausroll/core/exceptions.h>
#include <ausroll/core/parse_utilities.h>

#include <cmath>

#include <deal.II/base/numbers.h>

namespace ausroll::contact::surfaces
{
  using namespace dealii;

  RevolvedProfile::RevolvedProfile(const geometry::CurveChain &profile,
                                   const Point<3>             &center,
                                   const Tensor<1, 3>         &axis,
                                   const Tensor<1, 3>         &reference)
      : chain(profile)
      , frame(center, axis, reference)
  {
    double size = 0.;
    for (unsigned int i = 0; i < chain.n_segments(); ++i)
    {
      const geometry::CurveSegment &seg = chain.segment(i);
      if (!seg.is_bounded())
      {
        // an infinite line must run parallel to the axis at r >= 0
        const Point<2>     p = seg.point(0.);
        const Tensor<1, 2> t = seg.tangent(0.);
        if (std::abs(t[0]) > 1e-12 || p[0] < 0.)
          throw EntryError("Profile/Points",
                           "an infinite profile line must be parallel to the axis, at r >= 0");
        size = std::max(size, std::abs(p[0]));
        continue;
      }
      size = std::max({size,
                       std::abs(seg.bounding_box_min()[0]),
                       std::abs(seg.bounding_box_max()[0]),
                       std::abs(seg.bounding_box_min()[1]),
                       std::abs(seg.bounding_box_max()[1])});
    }
    axis_tolerance = 1e-10 * std::max(size, 1e-300);
    const auto rim = [&](const double s)
    { return std::isfinite(s) && std::abs(chain.point_at(s)[0]) > axis_tolerance; };
    rim_at_start = rim(chain.outline().first);
    rim_at_end = rim(chain.outline().second);
    for (unsigned int i = 0; i < chain.n_segments(); ++i)
      if (chain.segment(i).is_bounded() && chain.segment(i).bounding_box_min()[0] < -axis_tolerance)
      {
        // the bounding box of an arc is that of its points: check finely
        const geometry::CurveSegment &seg = chain.segment(i);
        const unsigned int            n = 64;
        for (unsigned int k = 0; k <= n; ++k)
          if (seg.point(seg.u_begin() + seg.length() * k / n)[0] < -axis_tolerance)
            throw EntryError("Profile/Points",
                             "the profile must lie in the half plane r >= 0 (its x coordinate "
                             "is the distance from the axis)");
      }
  }

  SurfaceProjection<3> RevolvedProfile::project(const Point<3> &x, const double max_distance) const
  {
    const Point<3>             xi = frame.to_canonical(x);
    const SurfaceProjection<2> q
        = chain.project(Point<2>(std::hypot(xi[0], xi[1]), xi[2]), max_distance);
    if (!q.valid)
      return SurfaceProjection<3>();
    MeridianProjection m;
    m.point = q.point;
    m.normal = q.normal;
    m.gap = q.gap;
    m.curvature = q.curvatures[0];
    m.s = q.coordinates[0];
    m.at_edge = q.at_edge;
    m.at_end = q.at_end;
    // an end of the profile on the axis is no rim of the surface
    m.end_margin = chain.outline_margin(q.coordinates[0], rim_at_start, rim_at_end);
    if (q.at_end && std::abs(q.point[0]) <= axis_tolerance)
    {
      // an end on the axis: a smooth point if the profile meets the axis at a right angle (a face
      // through the axis), else a vertex (an edge)
      const bool                    first = q.coordinates[0] <= chain.s_begin() + axis_tolerance;
      const geometry::CurveSegment &seg = chain.segment(first ? 0 : chain.n_segments() - 1);
      const double                  u = first ? seg.u_begin() : seg.u_end();
      const Tensor<1, 2>            n = seg.normal(u);
      m.at_end = false;
      m.at_edge = std::abs(n[0]) > 1e-10;
      if (!m.at_edge)
      {
        m.normal = n;
        m.gap = (Point<2>(std::hypot(xi[0], xi[1]), xi[2]) - q.point) * n;
        m.curvature = seg.curvature(u);
      }
    }
    SurfaceProjection<3> p = revolve_meridian_projection(xi, m, axis_tolerance);
    frame.to_local(p);
    return p;
  }

  Point<3> RevolvedProfile::point_at(const std::array<double, 2> &coordinates) const
  {
    const Point<2> m = chain.point_at(coordinates[0]); // (r, z)
    const double   theta = coordinates[1];
    return frame.to_local(Point<3>(m[0] * std::cos(theta), m[0] * std::sin(theta), m[1]));
  }

  std::array<double, 2> RevolvedProfile::coordinate_periods() const
  {
    return {{chain.is_closed() ? chain.total_length() : 0., 2. * numbers::PI}};
  }

  void RevolvedProfileParameters::declare_parameters(ParameterHandler &prm)
  {
    declare_placement(prm,
                      "Center",
                      "Origin of the meridian coordinates (r, z) on the axis (x, y, z).",
                      "Direction of the axis of revolution (z of the profile; nonzero).",
                      "Direction of theta = 0 for the surface coordinates.");
    ProfileParameters::declare_parameters(prm, "r, z");
  }

  void RevolvedProfileParameters::parse(ParameterHandler  &prm,
                                        const std::string &path,
                                        const std::string &input_directory)
  {
    parse_placement(prm, "Center", path, center, axis, reference);
    profile.parse_parameters(prm, path, input_directory);
  }

  std::unique_ptr<const RigidSurface<3>>
  RevolvedProfileParameters::create(const std::string &path) const
  {
    const geometry::CurveChain chain = profile.create();
    return with_path(path,
                     [&]() -> std::unique_ptr<const RigidSurface<3>>
                     { return std::make_unique<RevolvedProfile>(chain, center, axis, reference); });
  }
} // namespace ausroll::contact::surfaces

AUSROLL_REGISTER_DIE_SHAPE(3,
                           ausroll::contact::surfaces::RevolvedProfileParameters,
                           "revolved profile",
                           "Revolved profile",
                           "the surface of revolution of a 2D Profile chain (r, z) about Axis")
