/**
 * @file quadrature_interpolation.h
 * Lagrange interpolation of quadrature-point data (stress, plastic strain) inside a cell.
 */
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/fe/fe_dgq.h>

#include <vector>

namespace ausroll::mechanics
{
  /**
   * The tensor-product Lagrange polynomial through the n^dim Gauss points of QGauss<dim>(n):
   * f(xi) = sum_q w_q(xi) f_q. Exact for quadrature data that is a polynomial of degree n-1 per
   * direction; used to sample stresses at arbitrary points (line probes) and to move material-point
   * data to the quadrature points of refined cells.
   */
  template <int dim>
  class QuadratureInterpolation
  {
  public:
    /** Interpolation through the points of QGauss<dim>(@p n_points_1d). */
    explicit QuadratureInterpolation(const unsigned int n_points_1d);

    /** Weights w_q at @p unit_point, in the order of the QGauss<dim> points. */
    std::vector<double> weights(const dealii::Point<dim> &unit_point) const;

  private:
    dealii::FE_DGQArbitraryNodes<dim> fe;         ///< Lagrange basis on the Gauss points
    std::vector<unsigned int>         qp_of_node; ///< quadrature index of each basis function
  };
} // namespace ausroll::mechanics
