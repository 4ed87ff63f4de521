/**
 * @file plastic_strain.cc
 * Refinement indicator `plastic strain`: max - min of the equivalent plastic strain over a cell's
 * material points, marked with fixed fractions (the elastic-plastic front and strong gradients).
 */
#include <ausroll/adaptivity/refinement_indicators.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <limits>

namespace ausroll::adaptivity
{
  using namespace dealii;

  /** `Indicators = plastic strain`. */
  class PlasticStrainIndicator : public IndicatorBase<PlasticStrainIndicator>
  {
  public:
    template <int dim>
    void mark_cells(const IndicatorInput<dim> &in, CellFlags &flags) const
    {
      Vector<float> indicator(in.triangulation.n_active_cells());
      double        largest = 0.;
      for (const auto &cell : in.triangulation.active_cell_iterators())
        if (cell->is_locally_owned())
        {
          double lo = std::numeric_limits<double>::max(), hi = 0.;
          for (const auto &point : in.material_points.get_data(cell))
          {
            lo = std::min(lo, point->committed.equivalent_plastic_strain);
            hi = std::max(hi, point->committed.equivalent_plastic_strain);
          }
          indicator[cell->active_cell_index()] = hi - lo;
          largest = std::max(largest, hi - lo);
        }
      if (Utilities::MPI::max(largest, in.triangulation.get_communicator()) > 0.)
        fixed_fraction_flags(in, indicator, flags);
    }
  };
} // namespace ausroll::adaptivity

AUSROLL_REGISTER_REFINEMENT_INDICATOR(ausroll::adaptivity::PlasticStrainIndicator,
                                      "plastic strain",
                                      "variation of the equivalent plastic strain within a cell")
