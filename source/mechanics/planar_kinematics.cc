#include <ausroll/mechanics/planar_kinematics.h>

#include <deal.II/base/numbers.h>

namespace ausroll::mechanics
{
  using dealii::Point;
  using dealii::Tensor;

  template <int dim>
  PlanarKinematics<dim>::PlanarKinematics(const PlanarModel model,
                                          const double      thickness,
                                          const double     *out_of_plane_stretch)
      : model(model)
      , thickness(thickness)
      , stretch(out_of_plane_stretch)
  {
  }

  template <int dim>
  Tensor<2, 3> PlanarKinematics<dim>::deformation_gradient(const Tensor<2, dim> &grad_u,
                                                           const Tensor<1, dim> &u,
                                                           const Point<dim>     &X) const
  {
    Tensor<2, 3> F = shape_gradient(grad_u, u, X);
    for (unsigned int i = 0; i < 3; ++i)
      F[i][i] += 1.;
    if (is_generalized_plane_strain())
      F[2][2] = out_of_plane_stretch();
    return F;
  }

  template <int dim>
  Tensor<2, 3> PlanarKinematics<dim>::shape_gradient(const Tensor<2, dim> &grad_phi,
                                                     const Tensor<1, dim> &phi,
                                                     const Point<dim>     &X) const
  {
    Tensor<2, 3> G;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        G[i][j] = grad_phi[i][j];
    if (is_axisymmetric())
      G[2][2] = phi[0] / X[0];
    return G;
  }

  template <int dim>
  double PlanarKinematics<dim>::volume_factor(const Point<dim> &X) const
  {
    if (dim == 3)
      return 1.;
    if (model == PlanarModel::axisymmetric)
      return 2. * dealii::numbers::PI * X[0];
    return thickness;
  }

  template class PlanarKinematics<2>;
  template class PlanarKinematics<3>;
} // namespace ausroll::mechanics
