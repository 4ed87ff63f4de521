#include <ausroll/contact/surfaces/frame_3d.h>
#include <ausroll/core/exceptions.h>

#include <cmath>

namespace ausroll::contact::surfaces
{
  using namespace dealii;

  Frame3D::Frame3D()
  {
    for (unsigned int i = 0; i < 3; ++i)
      e[i][i] = 1.;
  }

  Frame3D::Frame3D(const Point<3> &origin, const Tensor<1, 3> &axis, const Tensor<1, 3> &reference)
      : o(origin)
  {
    const double a = axis.norm();
    if (!(a > 0.) || !std::isfinite(a))
      throw InputError("the axis of a 3D surface must be a nonzero vector");
    e[2] = axis / a;
    Tensor<1, 3> r = reference - (reference * e[2]) * e[2];
    if (r.norm() <= 1e-12 * reference.norm() || !(r.norm() > 0.))
      r = perpendicular(e[2]);
    e[0] = r / r.norm();
    e[1] = cross_product_3d(e[2], e[0]);
  }

  Point<3> Frame3D::to_canonical(const Point<3> &x) const
  {
    const Tensor<1, 3> d = x - o;
    return Point<3>(d * e[0], d * e[1], d * e[2]);
  }

  Point<3> Frame3D::to_local(const Point<3> &xi) const
  {
    return o + xi[0] * e[0] + xi[1] * e[1] + xi[2] * e[2];
  }

  Tensor<1, 3> Frame3D::vector_to_local(const Tensor<1, 3> &v) const
  {
    return v[0] * e[0] + v[1] * e[1] + v[2] * e[2];
  }

  void Frame3D::to_local(SurfaceProjection<3> &p) const
  {
    p.point = to_local(p.point);
    p.normal = vector_to_local(p.normal);
    for (auto &t : p.tangents)
      t = vector_to_local(t);
  }

  Tensor<1, 3> Frame3D::perpendicular(const Tensor<1, 3> &n)
  {
    unsigned int k = 0; // axis least aligned with n
    for (unsigned int i = 1; i < 3; ++i)
      if (std::abs(n[i]) < std::abs(n[k]))
        k = i;
    Tensor<1, 3> ek;
    ek[k] = 1.;
    const Tensor<1, 3> p = ek - (ek * n) * n;
    return p / p.norm();
  }

  SurfaceProjection<3> revolve_meridian_projection(const Point<3>           &x,
                                                   const MeridianProjection &m,
                                                   const double              axis_tolerance)
  {
    const double r = std::hypot(x[0], x[1]);
    Tensor<1, 3> e_r, e_theta, e_z;
    e_z[2] = 1.;
    if (r > 0.)
    {
      e_r[0] = x[0] / r;
      e_r[1] = x[1] / r;
    }
    else
      e_r[0] = 1.; // on the axis: theta = 0
    e_theta[0] = -e_r[1];
    e_theta[1] = e_r[0];

    SurfaceProjection<3> p;
    p.valid = true;
    p.point = Point<3>(m.point[0] * e_r + m.point[1] * e_z);
    p.normal = m.normal[0] * e_r + m.normal[1] * e_z;
    p.gap = m.gap;
    p.distance = std::abs(m.gap);
    // t_m = (n_z, -n_r) in the meridian plane
    p.tangents[0] = m.normal[1] * e_r - m.normal[0] * e_z;
    p.tangents[1] = e_theta;
    p.coordinates[0] = m.s;
    p.coordinates[1] = r > 0. ? std::atan2(x[1], x[0]) : 0.;
    const bool on_axis = std::abs(m.point[0]) <= axis_tolerance;
    p.at_edge = m.at_edge || m.at_end;
    p.at_end = m.at_end;
    p.end_margin = m.end_margin;
    if (p.at_edge || p.at_end)
      p.curvatures = {{0., 0.}};
    else
      p.curvatures = {{m.curvature, on_axis ? m.curvature : m.normal[0] / m.point[0]}};
    return p;
  }
} // namespace ausroll::contact::surfaces
