/**
 * @file elasticity.h
 * Isotropic linear elasticity in three dimensions (the material point always works in 3D;
 * plane strain, plane stress and axisymmetry are handled by the kinematics).
 */
#pragma once

#include <deal.II/base/symmetric_tensor.h>

namespace ausroll::material
{
  /**
   * Isotropic elastic moduli (set by `Material/Young's modulus` and `Material/Poisson's ratio`).
   */
  class IsotropicElasticity
  {
  public:
    /** Moduli from Young's modulus @p E and Poisson's ratio @p nu. */
    IsotropicElasticity(const double E, const double nu)
        : youngs_modulus(E)
        , poissons_ratio(nu)
        , shear_modulus(E / (2. * (1. + nu)))
        , bulk_modulus(E / (3. * (1. - 2. * nu)))
        , lame_lambda(E * nu / ((1. + nu) * (1. - 2. * nu)))
    {
    }

    /** sigma = C : eps. */
    dealii::SymmetricTensor<2, 3> stress(const dealii::SymmetricTensor<2, 3> &strain) const
    {
      return lame_lambda * dealii::trace(strain) * dealii::unit_symmetric_tensor<3>()
             + 2. * shear_modulus * strain;
    }

    /** eps = C^-1 : sigma (the inverse of stress()). */
    dealii::SymmetricTensor<2, 3> strain(const dealii::SymmetricTensor<2, 3> &stress) const
    {
      const double                  mean = dealii::trace(stress) / 3.;
      dealii::SymmetricTensor<2, 3> eps = (0.5 / shear_modulus) * stress;
      const double volumetric = mean / (3. * bulk_modulus) - mean / (2. * shear_modulus);
      for (unsigned int i = 0; i < 3; ++i)
        eps[i][i] += volumetric;
      return eps;
    }

    /** The elasticity tensor C = 3 kappa I_vol + 2 mu I_dev. */
    dealii::SymmetricTensor<4, 3> stiffness() const
    {
      return 3. * bulk_modulus
                 * dealii::outer_product(dealii::unit_symmetric_tensor<3>(),
                                         dealii::unit_symmetric_tensor<3>())
                 / 3.
             + 2. * shear_modulus * dealii::deviator_tensor<3>();
    }

    const double youngs_modulus; ///< E
    const double poissons_ratio; ///< nu
    const double shear_modulus;  ///< mu = E / (2 (1 + nu))
    const double bulk_modulus;   ///< kappa = E / (3 (1 - 2 nu))
    const double lame_lambda;    ///< lambda = E nu / ((1 + nu)(1 - 2 nu))
  };
} // namespace ausroll::material
