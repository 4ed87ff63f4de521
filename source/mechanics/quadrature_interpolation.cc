#include <ausroll/mechanics/quadrature_interpolation.h>

#include <deal.II/base/quadrature_lib.h>

namespace ausroll::mechanics
{
  using namespace dealii;

  template <int dim>
  QuadratureInterpolation<dim>::QuadratureInterpolation(const unsigned int n_points_1d)
      : fe(QGauss<1>(n_points_1d))
  {
    // Match the element's support points with the quadrature points (do not rely on orderings).
    const QGauss<dim>              quadrature(n_points_1d);
    const std::vector<Point<dim>> &support = fe.get_unit_support_points();
    qp_of_node.resize(support.size());
    for (unsigned int i = 0; i < support.size(); ++i)
      for (unsigned int q = 0; q < quadrature.size(); ++q)
        if (support[i].distance(quadrature.point(q)) < 1e-12)
          qp_of_node[i] = q;
  }

  template <int dim>
  std::vector<double> QuadratureInterpolation<dim>::weights(const Point<dim> &unit_point) const
  {
    std::vector<double> w(qp_of_node.size());
    for (unsigned int i = 0; i < qp_of_node.size(); ++i)
      w[qp_of_node[i]] = fe.shape_value(i, unit_point);
    return w;
  }

  template class QuadratureInterpolation<2>;
  template class QuadratureInterpolation<3>;
} // namespace ausroll::mechanics
