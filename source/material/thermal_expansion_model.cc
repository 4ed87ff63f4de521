#include <ausroll/material/thermal_expansion_model.h>

#include <deal.II/base/symmetric_tensor.h>

namespace ausroll::material
{
  using namespace dealii;

  ThermalExpansionModel::ThermalExpansionModel(std::unique_ptr<ConstitutiveModel> inner_model,
                                               const PropertyTable               &alpha,
                                               const double                       t_ref)
      : WrappedModel(std::move(inner_model))
      , expansion(alpha)
      , reference_temperature(t_ref)
  {
  }

  double ThermalExpansionModel::thermal_stretch(const double temperature) const
  {
    return 1. + expansion.value(temperature) * (temperature - reference_temperature);
  }

  void ThermalExpansionModel::evaluate(const Tensor<2, 3>  &F,
                                       const MaterialState &old,
                                       MaterialState       &state,
                                       Tensor<2, 3>        &P,
                                       Tensor<4, 3>        *tangent) const
  {
    const double theta = thermal_stretch(old.temperature);
    inner->evaluate(remove_stretch(F, theta), old, state, P, tangent);
    scale_response(P, tangent, theta);
    state.temperature = old.temperature;
    state.evaluation_temperature = old.temperature;
    const double d_alpha = state.equivalent_plastic_strain - old.equivalent_plastic_strain;
    const double J = inner->is_small_strain() ? 1. : determinant(F);
    state.plastic_work
        = old.plastic_work
          + (d_alpha > 0. ? 0.5 * J * (old.von_mises_stress() + state.von_mises_stress()) * d_alpha
                          : 0.);
  }

  void ThermalExpansionModel::rebase(MaterialState &state, const Tensor<2, 3> &F) const
  {
    // the stored state excludes the thermal stretch of the temperature it was evaluated at; the
    // thermal field has since written the step's new temperature into state.temperature, whose
    // stretch the next evaluation applies (using it here lost one step of thermal strain at
    // every adaptation while the temperature changed)
    inner->rebase(state, remove_stretch(F, thermal_stretch(state.evaluation_temperature)));
  }
} // namespace ausroll::material
