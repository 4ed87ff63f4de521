#include <ausroll/solver/loading_parameters.h>
#include <ausroll/solver/step_control.h>

namespace ausroll::solver
{
  std::unique_ptr<StepControl> create_step_control(const LoadingParameters &loading)
  {
    if (loading.step_control_parameters)
      return loading.step_control_parameters->create(loading.step_growth_factor);
    return StepControlRegistry::instance()
        .get(loading.step_control, "Loading/Step control")
        .make()
        ->create(loading.step_growth_factor);
  }
} // namespace ausroll::solver
