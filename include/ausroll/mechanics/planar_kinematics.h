/**
 * @file planar_kinematics.h
 * Embedding of a dim-dimensional displacement field into 3x3 deformation gradients.
 */
#pragma once

#include <ausroll/mechanics/model_parameters.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

namespace ausroll::mechanics
{
  /**
   * Maps displacement gradients of a planar (dim = 2) or 3D model to the 3x3 deformation gradient
   * the material points work with, and gives the volume measure. Set by `Model/Planar model` and
   * `Model/Thickness`.
   *  - plane strain: F_zz = 1; dV = thickness dA.
   *  - plane stress: F_zz = 1 here, the PlaneStressDriver finds the actual stretch; dV = thickness
   * dA.
   *  - axisymmetric: (x, y) = (r, z); F_thetatheta = 1 + u_r / r; dV = 2 pi r dA.
   * For dim = 3 the embedding is the identity.
   */
  template <int dim>
  class PlanarKinematics
  {
  public:
    /** Kinematics of @p model with out-of-plane @p thickness (ignored when axisymmetric). */
    PlanarKinematics(const PlanarModel model, const double thickness);

    /** F = I + Grad u embedded in 3D, at reference point @p X with displacement @p u. */
    dealii::Tensor<2, 3> deformation_gradient(const dealii::Tensor<2, dim> &grad_u,
                                              const dealii::Tensor<1, dim> &u,
                                              const dealii::Point<dim>     &X) const;

    /**
     * The 3D gradient dF/du_i of a vector-valued shape function with value @p phi and gradient
     * @p grad_phi (the variation of F caused by that shape function).
     */
    dealii::Tensor<2, 3> shape_gradient(const dealii::Tensor<2, dim> &grad_phi,
                                        const dealii::Tensor<1, dim> &phi,
                                        const dealii::Point<dim>     &X) const;

    /** Factor turning the reference area element dA into the volume element dV. */
    double volume_factor(const dealii::Point<dim> &X) const;

    /**
     * Number n of directions that carry volume change in the F-bar method, for the cell-centre J0
     * of Q1 (@p mean_dilatation false) or the cell-average J0 of Q2 and higher (true): 3 for 3D
     * and axisymmetric models (the whole F, hoop stretch included, is scaled); 2 for plane stress
     * (only the in-plane block, F_zz comes from sigma_zz = 0); plane strain 2 for Q1 (F_bar_zz = 1)
     * and 3 with mean dilatation (F_bar_zz = s, as Hughes' B-bar with eps_bar_zz = (theta_0 -
     * theta) / 3: the in-plane scaling leaks the volume correction into the 3D deviatoric strain
     * and made Q2 too soft, flat punch 0.928 p_lim instead of 0.998).
     */
    unsigned int volumetric_dimensions(const bool mean_dilatation) const
    {
      if (dim == 3 || is_axisymmetric())
        return 3;
      return mean_dilatation && model == PlanarModel::plane_strain ? 3 : 2;
    }

    /** True for the axisymmetric model (shape function values enter the gradient). */
    bool is_axisymmetric() const { return model == PlanarModel::axisymmetric && dim == 2; }

    /** The planar model. */
    PlanarModel planar_model() const { return model; }

  private:
    PlanarModel model;     ///< idealisation
    double      thickness; ///< out-of-plane thickness of plane models
  };
} // namespace ausroll::mechanics
