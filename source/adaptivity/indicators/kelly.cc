/**
 * @file kelly.cc
 * Refinement indicator `Kelly`: the KellyErrorEstimator of the displacement (jumps of its
 * gradient across faces), marked with fixed fractions (`Refine fraction`, `Coarsen fraction`).
 */
#include <ausroll/adaptivity/refinement_indicators.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/numerics/error_estimator.h>

namespace ausroll::adaptivity
{
  using namespace dealii;

  /** `Indicators = Kelly`. */
  class KellyIndicator : public IndicatorBase<KellyIndicator>
  {
  public:
    template <int dim>
    void mark_cells(const IndicatorInput<dim> &in, CellFlags &flags) const
    {
      Vector<float> indicator(in.triangulation.n_active_cells());
      KellyErrorEstimator<dim>::estimate(in.mapping,
                                         in.dof_handler,
                                         QGauss<dim - 1>(in.dof_handler.get_fe().degree + 1),
                                         {},
                                         in.solution,
                                         indicator,
                                         ComponentMask(),
                                         nullptr,
                                         numbers::invalid_unsigned_int,
                                         in.triangulation.locally_owned_subdomain());
      fixed_fraction_flags(in, indicator, flags);
    }
  };
} // namespace ausroll::adaptivity

AUSROLL_REGISTER_REFINEMENT_INDICATOR(ausroll::adaptivity::KellyIndicator,
                                      "Kelly",
                                      "jumps of the displacement gradient")
