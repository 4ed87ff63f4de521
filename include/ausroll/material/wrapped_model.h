/**
 * @file wrapped_model.h
 * Base of the constitutive models that wrap another one (plane stress, thermal strain).
 */
#pragma once

#include <ausroll/material/constitutive_model.h>

#include <deal.II/base/symmetric_tensor.h>

#include <memory>

namespace ausroll::material
{
  /**
   * A ConstitutiveModel around an inner model: passes through what the wrapper does not change
   * (small-strain flag, plasticity, yield function, projection onto the yield surface); derived
   * classes implement evaluate() and, where they change the deformation gradient the inner model
   * sees, rebase().
   */
  class WrappedModel : public ConstitutiveModel
  {
  public:
    /** Wrap @p model. */
    explicit WrappedModel(std::unique_ptr<ConstitutiveModel> model)
        : inner(std::move(model))
    {
    }

    bool is_small_strain() const override { return inner->is_small_strain(); }

    /** The inner model's yield function. */
    double yield_function(const MaterialState &state) const override
    {
      return inner->yield_function(state);
    }

    /** The inner model's projection. */
    void make_admissible(MaterialState &state) const override { inner->make_admissible(state); }

    const PlasticityModel &plasticity() const override { return inner->plasticity(); }

    /** Passed on to the inner model. */
    void set_step_length(const double dt) override { inner->set_step_length(dt); }

  protected:
    /**
     * An isotropic stretch theta of the intermediate configuration (thermal or transformation
     * strain): the deformation gradient the inner model sees at total @p F, F / theta
     * (multiplicative), or F - (theta - 1) I for a small-strain inner model (additive strain).
     */
    dealii::Tensor<2, 3> remove_stretch(const dealii::Tensor<2, 3> &F, const double theta) const
    {
      if (inner->is_small_strain())
        return F - (theta - 1.) * dealii::Tensor<2, 3>(dealii::unit_symmetric_tensor<3>());
      return F / theta;
    }

    /** The inner model's response at remove_stretch(F, theta) per unit reference volume:
        W(F) = theta^3 W_inner(F / theta), so P = theta^2 P_inner and dP/dF = theta dP_inner/dF
        (small strain: unchanged). */
    void
    scale_response(dealii::Tensor<2, 3> &P, dealii::Tensor<4, 3> *tangent, const double theta) const
    {
      if (inner->is_small_strain())
        return;
      P *= theta * theta;
      if (tangent != nullptr)
        *tangent *= theta;
    }

    std::unique_ptr<ConstitutiveModel> inner; ///< the wrapped model
  };
} // namespace ausroll::material
