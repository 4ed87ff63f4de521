#include <ausroll/contact/surfaces/plane.h>
#include <ausroll/contact/surfaces/shape_entries_3d.h>
#include <ausroll/core/exceptions.h>
#include <ausroll/core/parse_utilities.h>

#include <algorithm>
#include <cmath>

namespace ausroll::contact::surfaces
{
  using namespace dealii;

  Plane::Plane(const Point<3>     &point,
               const Tensor<1, 3> &normal,
               const Tensor<1, 3> &first_tangent,
               const double        half_length_1,
               const double        half_length_2)
      : frame(point, normal, first_tangent)
      , half{half_length_1, half_length_2}
  {
    if (!(half_length_1 > 0.) || !(half_length_2 > 0.))
      throw InputError("plane: the half lengths of the rectangle must be positive");
  }

  SurfaceProjection<3> Plane::project(const Point<3> &x, const double max_distance) const
  {
    const Point<3> xi = frame.to_canonical(x);
    // canonical frame: the plane is xi_2 = 0, n = +e3
    const double c0 = std::clamp(xi[0], -half[0], half[0]);
    const double c1 = std::clamp(xi[1], -half[1], half[1]);

    SurfaceProjection<3> p;
    p.point = Point<3>(c0, c1, 0.);
    p.coordinates = {{c0, c1}};
    p.curvatures = {{0., 0.}};
    Tensor<1, 3> n, t1, t2;
    t1[0] = 1.;
    t2[1] = 1.;
    n[2] = 1.;
    if (c0 == xi[0] && c1 == xi[1])
    {
      p.gap = xi[2];
      // distance to the nearer edge of a finite rectangle (+infinity for an infinite plane)
      p.end_margin = std::min(half[0] - std::abs(xi[0]), half[1] - std::abs(xi[1]));
      p.normal = n;
    }
    else
    {
      // beyond the rectangle: the normal points from its boundary to x
      const Tensor<1, 3> v = xi - p.point;
      const double       dist = v.norm();
      const double       side = xi[2] >= 0. ? 1. : -1.;
      p.gap = side * dist;
      p.normal = v / p.gap;
      // tangents: the boundary direction and n x it
      const Tensor<1, 3> along = (c0 != xi[0] && c1 != xi[1]) ? cross_product_3d(p.normal, t1)
                                 : c0 != xi[0]                ? t2
                                                              : t1;
      t2 = along - (along * p.normal) * p.normal;
      if (t2.norm() < 1e-12)
        t2 = Frame3D::perpendicular(p.normal);
      t2 /= t2.norm();
      t1 = cross_product_3d(t2, p.normal);
      p.at_edge = true;
      p.at_end = true;
    }
    p.distance = std::abs(p.gap);
    if (!(p.distance <= max_distance))
      return SurfaceProjection<3>();
    p.tangents = {{t1, t2}};
    p.valid = true;
    frame.to_local(p);
    return p;
  }

  Point<3> Plane::point_at(const std::array<double, 2> &coordinates) const
  {
    return frame.to_local(Point<3>(std::clamp(coordinates[0], -half[0], half[0]),
                                   std::clamp(coordinates[1], -half[1], half[1]),
                                   0.));
  }

  void PlaneParameters::declare_parameters(ParameterHandler &prm)
  {
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
  }

  void PlaneParameters::parse(ParameterHandler &prm, const std::string &path, const std::string &)
  {
    point = parse_point<3>(prm.get("Point"), path + "Point");
    normal = get_direction(prm, "Normal", path + "Normal");
    first_tangent = get_vector(prm, "First tangent", path + "First tangent");
    half_length_1 = prm.get_double("Half length 1");
    half_length_2 = prm.get_double("Half length 2");
  }

  std::unique_ptr<const RigidSurface<3>> PlaneParameters::create(const std::string &) const
  {
    const double inf = std::numeric_limits<double>::infinity();
    return std::make_unique<Plane>(point,
                                   normal,
                                   first_tangent,
                                   half_length_1 > 0. ? half_length_1 : inf,
                                   half_length_2 > 0. ? half_length_2 : inf);
  }
} // namespace ausroll::contact::surfaces

AUSROLL_REGISTER_DIE_SHAPE(3,
                           ausroll::contact::surfaces::PlaneParameters,
                           "plane",
                           "Plane",
                           "a plane through Point with the outward Normal, infinite or a rectangle")
