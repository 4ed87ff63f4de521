#include <ausroll/contact/surfaces/plane.h>
#include <ausroll/core/exceptions.h>

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
} // namespace ausroll::contact::surfaces
