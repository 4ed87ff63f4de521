// The curvature term of a slipping node's tangent on a curved die, 2D (3D: at the end)
// (contact/tangent/curvature_tangent.h) against the central difference of the condensed equation
// E(u_b) = v(x) . T(x) r on a circle (r held fixed, so that the difference is the geometric part
// alone). Reference: the exact derivative of the same formula; tolerance 1e-6 relative (difference
// step 1e-5 mm, the truncation error is of order (step / radius)^2).
#include <ausroll/contact/tangent/curvature_tangent.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace
{
  using namespace dealii;
  using ausroll::contact::CurvatureTangent;

  struct CircleNode
  {
    Point<2> center{0., 10.};
    double   radius = 10.;
    double   mu_s = 0.;    // Coulomb slope times slip sign (0: frictionless)
    unsigned a = 1, b = 0; // constrained / free component

    Tensor<1, 2> normal(const Point<2> &x) const
    {
      // out of the die (the body is outside the circle)
      Tensor<1, 2> n = x - center;
      return n / n.norm();
    }
    static Tensor<1, 2> tangent(const Tensor<1, 2> &n)
    {
      Tensor<1, 2> t;
      t[0] = n[1];
      t[1] = -n[0];
      return t;
    }
    Tensor<2, 2> transform(const Point<2> &x) const
    {
      const Tensor<1, 2> n = normal(x), t = tangent(n);
      Tensor<2, 2>       T = outer_product(t, n) * mu_s;
      T[0][0] += 1.;
      T[1][1] += 1.;
      return T;
    }
    double condensed_equation(const Point<2> &x, const Tensor<1, 2> &r) const
    {
      const Tensor<1, 2> n = normal(x);
      Tensor<1, 2>       v;
      v[b] = 1.;
      v[a] = -n[b] / n[a];
      return v * (transform(x) * r);
    }
  };

  double check(const CircleNode &node, const double angle, const Tensor<1, 2> &r)
  {
    const Point<2>     x0 = node.center + node.radius * Point<2>(std::sin(angle), -std::cos(angle));
    const Tensor<1, 2> n0 = node.normal(x0), t0 = CircleNode::tangent(n0);
    const double       c0 = -n0[node.b] / n0[node.a];
    Tensor<1, 2>       v0;
    v0[node.b] = 1.;
    v0[node.a] = c0;
    const double h = 1e-5;
    const double fd
        = (node.condensed_equation(x0 + h * v0, r) - node.condensed_equation(x0 - h * v0, r))
          / (2. * h);
    const Tensor<1, 2> dn_ds = t0 / node.radius; // circle: dn/ds = t / R
    const double       term
        = CurvatureTangent<2>::node_term(n0, dn_ds, t0, c0, r, node.transform(x0), node.a, node.b);
    EXPECT_NEAR(term, fd, 1e-6 * std::max(1., std::abs(fd)));
    return term;
  }
} // namespace

TEST(CurvatureTangent, FrictionlessNodeOnCircleMatchesDifference)
{
  CircleNode         node;
  const Tensor<1, 2> r{{300., 2000.}};
  for (const double angle : {0., 0.1, -0.25, 0.4})
    check(node, angle, r);
  // at the bottom of the punch (n = (0, -1)) the term is -(n . r) / R: the normal part of the
  // residual over the die radius
  EXPECT_NEAR(check(node, 0., Tensor<1, 2>{{0., 2000.}}), 2000. / 10., 1e-9);
}

TEST(CurvatureTangent, CoulombNodeOnCircleMatchesDifference)
{
  CircleNode node;
  node.mu_s = -0.3;
  const Tensor<1, 2> r{{-150., 2500.}};
  for (const double angle : {0.05, 0.3, -0.2})
    check(node, angle, r);
  node.mu_s = 0.3;
  check(node, 0.2, r);
}

TEST(CurvatureTangent, ConstrainedXComponent)
{
  // a node on the side of the circle: the x component is the constrained one
  CircleNode node;
  node.a = 0;
  node.b = 1;
  const Tensor<1, 2> r{{1800., -400.}};
  for (const double angle : {1.2, 1.5, 1.8})
    check(node, angle, r);
}

TEST(CurvatureTangent, FlatDieAddsNothing)
{
  const Tensor<1, 2> n{{0., -1.}}, t{{-1., 0.}};
  Tensor<2, 2>       T;
  T[0][0] = T[1][1] = 1.;
  EXPECT_EQ(
      CurvatureTangent<2>::node_term(n, Tensor<1, 2>(), t, 0., Tensor<1, 2>{{5., 7.}}, T, 1, 0),
      0.);
}

// The list of contact tangent terms (contact/tangent/contact_tangent_term.h) as the parameters
// ask for it: the slip direction always (it says itself when it adds nothing), the curvature
// only with `Contact/Curvature tangent = true` (2D and 3D).
TEST(ContactTangentTerms, ListFollowsParameters)
{
  using namespace ausroll::contact;
  const auto names = [](const auto &terms)
  {
    std::vector<std::string> n;
    for (const auto &term : terms)
      n.push_back(term->name());
    return n;
  };
  ContactParameters parameters;
  EXPECT_EQ(names(create_tangent_terms<2>(parameters)), std::vector<std::string>{"slip direction"});
  EXPECT_EQ(names(create_tangent_terms<3>(parameters)), std::vector<std::string>{"slip direction"});
  parameters.curvature_tangent = true;
  EXPECT_EQ(names(create_tangent_terms<2>(parameters)),
            (std::vector<std::string>{"slip direction", "curvature"}));
  EXPECT_EQ(names(create_tangent_terms<3>(parameters)),
            (std::vector<std::string>{"slip direction", "curvature"}));
}

// 3D: the block of CurvatureTangent::node_term_3d() against central differences of the condensed
// equations E_j(x) = v_j(x) . (T(x) r) of a slipping node on a cylinder with a tilted axis (the two
// principal curvatures 1/R and 0 are not along the coordinate axes), moved along the constraint
// x = x0 + v_j'(x0) h; r and the slip direction d in T = I + mu d (x) n held fixed (the change of
// d is SlipDirectionTangent's). Reference: the same formula differentiated numerically; tolerance
// 1e-6 relative (step 1e-5 mm, truncation error of order (step / R)^2).
namespace
{
  struct CylinderNode
  {
    Point<3>     center{1., 2., -3.};
    Tensor<1, 3> axis;
    double       radius = 8.;
    double       mu = 0.;
    Tensor<1, 3> d; // slip direction at x0 (tangent)

    Tensor<1, 3> normal(const Point<3> &x) const
    {
      Tensor<1, 3> n = (x - center) - ((x - center) * axis) * axis;
      return n / n.norm();
    }
    Tensor<2, 3> transform(const Point<3> &x) const
    {
      Tensor<2, 3> T = mu * outer_product(d, normal(x));
      for (unsigned int i = 0; i < 3; ++i)
        T[i][i] += 1.;
      return T;
    }
    static unsigned int largest(const Tensor<1, 3> &n)
    {
      unsigned int k = 0;
      for (unsigned int c = 1; c < 3; ++c)
        if (std::abs(n[c]) > std::abs(n[k]))
          k = c;
      return k;
    }
    static Tensor<1, 3> v(const Tensor<1, 3> &n, const unsigned int k, const unsigned int j)
    {
      Tensor<1, 3> w;
      w[j] = 1.;
      w[k] = -n[j] / n[k];
      return w;
    }
  };

  /** Largest difference between the analytic and the numerical block, relative to the largest
      entry of the numerical one. */
  double check_3d(CylinderNode &node, const Tensor<1, 3> &radial, const Tensor<1, 3> &r)
  {
    const Point<3>     x0 = node.center + node.radius * radial;
    const Tensor<1, 3> n0 = node.normal(x0);
    // tangents: along the axis (flat) and around it (curvature 1 / R), the exact dn/dt
    std::array<Tensor<1, 3>, 2> t{{node.axis, cross_product_3d(n0, node.axis)}};
    std::array<Tensor<1, 3>, 2> dn_dt{{Tensor<1, 3>(), t[1] / node.radius}};
    node.d = (0.6 * t[0] + 0.8 * t[1]);
    const unsigned int k = CylinderNode::largest(n0);
    const Tensor<2, 3> T0 = node.transform(x0);
    const Tensor<2, 3> term = CurvatureTangent<3>::node_term_3d(n0, dn_dt, t, k, r, T0);
    const double       h = 1e-5;
    double             largest = 0., error = 0.;
    for (unsigned int jj = 0; jj < 3; ++jj)
      if (jj != k)
      {
        const Tensor<1, 3> dx = CylinderNode::v(n0, k, jj);
        for (unsigned int j = 0; j < 3; ++j)
          if (j != k)
          {
            const auto E = [&](const Point<3> &x)
            { return CylinderNode::v(node.normal(x), k, j) * (node.transform(x) * r); };
            // the frozen part (what the assembled tangent holds) is constant in x: subtract
            // nothing, the full derivative of E at fixed r is the curvature term
            const double fd = (E(x0 + h * dx) - E(x0 - h * dx)) / (2. * h);
            largest = std::max(largest, std::abs(fd));
            error = std::max(error, std::abs(fd - term[j][jj]));
          }
      }
    EXPECT_GT(largest, 1e-3); // the term is not trivially zero here
    return error / largest;
  }

  CylinderNode tilted_cylinder(const double mu)
  {
    CylinderNode node;
    node.axis = Tensor<1, 3>{{0.3, -0.5, 0.8}};
    node.axis /= node.axis.norm();
    node.mu = mu;
    return node;
  }
} // namespace

TEST(CurvatureTangent3d, FrictionlessNodeOnTiltedCylinder)
{
  CylinderNode       node = tilted_cylinder(0.);
  const Tensor<1, 3> axis = node.axis;
  Tensor<1, 3>       radial = cross_product_3d(axis, Tensor<1, 3>{{0., 0., 1.}});
  radial /= radial.norm();
  EXPECT_LT(check_3d(node, radial, Tensor<1, 3>{{40., -25., 70.}}), 1e-6);
}

TEST(CurvatureTangent3d, CoulombNodeOnTiltedCylinder)
{
  CylinderNode node = tilted_cylinder(0.3);
  Tensor<1, 3> radial = cross_product_3d(node.axis, Tensor<1, 3>{{1., 0., 0.}});
  radial /= radial.norm();
  EXPECT_LT(check_3d(node, radial, Tensor<1, 3>{{-30., 55., 20.}}), 1e-6);
}
