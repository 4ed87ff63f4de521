#include <ausroll/contact/surfaces/extruded_profile.h>
#include <ausroll/contact/surfaces/shape_entries_3d.h>
#include <ausroll/core/exceptions.h>
#include <ausroll/core/parse_utilities.h>

#include <algorithm>
#include <cmath>

namespace ausroll::contact::surfaces
{
  using namespace dealii;

  ExtrudedProfile::ExtrudedProfile(const geometry::CurveChain &profile,
                                   const double                z0,
                                   const double                z1,
                                   const bool                  caps,
                                   const Point<3>             &origin,
                                   const Tensor<1, 3>         &axis,
                                   const Tensor<1, 3>         &reference)
      : chain(profile)
      , z_lo(z0)
      , z_hi(z1)
      , with_caps(caps)
      , frame(origin, axis, reference)
  {
    if (!(z0 < z1))
      throw EntryError("End z", "must be larger than Start z");
    if (caps && !(std::isfinite(z0) && std::isfinite(z1)))
      throw EntryError("End caps", "needs a finite extrusion (Start z and End z)");
  }

  SurfaceProjection<3> ExtrudedProfile::project(const Point<3> &x, const double max_distance) const
  {
    const Point<3> xi = frame.to_canonical(x);
    const double   z = xi[2], zc = std::clamp(z, z_lo, z_hi);
    // With caps a point inside the prism may be near a cap and far from the mantle: the full 2D
    // projection is needed to know whether (x, y) lies on the material side.
    const SurfaceProjection<2> q = chain.project(
        Point<2>(xi[0], xi[1]), with_caps ? std::numeric_limits<double>::infinity() : max_distance);
    if (!q.valid)
      return SurfaceProjection<3>();

    const Tensor<1, 3> n2({q.normal[0], q.normal[1], 0.});
    const Tensor<1, 3> t2({q.tangents[0][0], q.tangents[0][1], 0.});
    Tensor<1, 3>       e3;
    e3[2] = 1.;
    // signed axial distance to [z0, z1] (> 0 beyond an end, <= 0 within) and the nearer end
    const double dz = std::max(z - z_hi, z_lo - z);
    const double sz = z - z_hi > z_lo - z ? 1. : -1.;

    SurfaceProjection<3> p;
    p.coordinates = {{zc, q.coordinates[0]}};
    p.curvatures = {{0., 0.}};
    // the rims: the ends of the profile's outline and, without caps, the ends of the extrusion
    p.end_margin = with_caps ? q.end_margin : std::min({q.end_margin, z - z_lo, z_hi - z});
    auto on_mantle = [&]()
    {
      p.point = Point<3>(q.point[0], q.point[1], z);
      p.normal = n2;
      p.gap = q.gap;
      p.tangents = {{e3, t2}};
      p.curvatures = {{0., q.curvatures[0]}};
      p.at_edge = q.at_edge || q.at_end;
      p.at_end = q.at_end;
    };
    auto on_cap = [&]()
    {
      const double zs = sz > 0. ? z_hi : z_lo;
      p.point = Point<3>(xi[0], xi[1], zs);
      p.normal = sz * e3;
      p.gap = sz * (z - zs);
      Tensor<1, 3> ex, ey;
      ex[0] = 1.;
      ey[1] = 1.;
      p.tangents
          = sz > 0. ? std::array<Tensor<1, 3>, 2>{{ex, ey}} : std::array<Tensor<1, 3>, 2>{{ey, ex}};
      p.coordinates[0] = zs;
    };
    auto on_end_line = [&](const bool outside)
    {
      // a cap edge or an open end: x - x_proj is normal to the edge line
      p.point = Point<3>(q.point[0], q.point[1], zc);
      const Tensor<1, 3> v = xi - p.point;
      const double       dist = v.norm();
      p.gap = outside ? dist : -dist;
      p.normal = v / p.gap;
      p.tangents = {{cross_product_3d(t2, p.normal), t2}};
      p.at_edge = true;
    };

    if (dz <= 0.)
    {
      // within [z0, z1]
      if (with_caps && q.gap <= 0. && dz > q.gap)
        on_cap();
      else
        on_mantle();
    }
    else if (with_caps)
    {
      if (q.gap <= 0.)
        on_cap();
      else
        on_end_line(true);
    }
    else
    {
      on_end_line(q.gap >= 0.);
      p.at_end = true;
    }
    p.distance = std::abs(p.gap);
    if (!(p.distance <= max_distance))
      return SurfaceProjection<3>();
    p.valid = true;
    frame.to_local(p);
    return p;
  }

  Point<3> ExtrudedProfile::point_at(const std::array<double, 2> &coordinates) const
  {
    const Point<2> p = chain.point_at(coordinates[1]);
    return frame.to_local(Point<3>(p[0], p[1], std::clamp(coordinates[0], z_lo, z_hi)));
  }

  std::array<double, 2> ExtrudedProfile::coordinate_periods() const
  {
    return {{0., chain.is_closed() ? chain.total_length() : 0.}};
  }

  void ExtrudedProfileParameters::declare_parameters(ParameterHandler &prm)
  {
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
    ProfileParameters::declare_parameters(prm, "x, y");
  }

  void ExtrudedProfileParameters::parse(ParameterHandler  &prm,
                                        const std::string &path,
                                        const std::string &input_directory)
  {
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
  }

  std::unique_ptr<const RigidSurface<3>>
  ExtrudedProfileParameters::create(const std::string &path) const
  {
    const geometry::CurveChain chain = profile.create();
    const double               inf = std::numeric_limits<double>::infinity();
    const bool                 finite = extent != Extent::infinite;
    return with_path(path,
                     [&]() -> std::unique_ptr<const RigidSurface<3>>
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
} // namespace ausroll::contact::surfaces

AUSROLL_REGISTER_DIE_SHAPE(
    3,
    ausroll::contact::surfaces::ExtrudedProfileParameters,
    "extruded profile",
    "Extruded profile",
    "a 2D Profile chain (x, y) extruded along Axis (infinite, finite, or with end caps)")
