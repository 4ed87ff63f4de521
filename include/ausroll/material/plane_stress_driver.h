/**
 * @file plane_stress_driver.h
 * Plane stress for any 3D constitutive model by local condensation (`Model/Planar model = plane
 * stress`).
 */
#pragma once

#include <ausroll/material/wrapped_model.h>

namespace ausroll::material
{
  /**
   * Wraps a 3D model and finds the out-of-plane stretch F_zz with P_zz = 0 by a local Newton
   * iteration (started from the committed F_zz). The returned tangent is the condensed one,
   * A_red = A - A[.,.,z,z] (x) A[z,z,.,.] / A[z,z,z,z], so that the global Newton iteration stays
   * quadratic. The out-of-plane shear components are zero in a planar problem.
   */
  class PlaneStressDriver : public WrappedModel
  {
  public:
    /** Driver around the 3D model @p model. */
    explicit PlaneStressDriver(std::unique_ptr<ConstitutiveModel> model);

    void evaluate(const dealii::Tensor<2, 3> &F,
                  const MaterialState        &old,
                  MaterialState              &state,
                  dealii::Tensor<2, 3>       &P,
                  dealii::Tensor<4, 3>       *tangent) const override;

    /** The inner model's rebase with the state's own out-of-plane stretch. */
    void rebase(MaterialState &state, const dealii::Tensor<2, 3> &F) const override;
  };
} // namespace ausroll::material
