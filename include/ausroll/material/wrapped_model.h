/**
 * @file wrapped_model.h
 * Base of the constitutive models that wrap another one (plane stress, thermal strain).
 */
#pragma once

#include <ausroll/material/constitutive_model.h>

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

  protected:
    std::unique_ptr<ConstitutiveModel> inner; ///< the wrapped model
  };
} // namespace ausroll::material
