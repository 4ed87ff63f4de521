/**
 * @file contact.cc
 * Refinement indicator `contact`: cells whose deformed centre is near a die now or at the next
 * step (`Contact band`, graded by `Fine contact band`, coarsened beyond `Coarsening distance`).
 */
#include <ausroll/adaptivity/refinement_indicators.h>

#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>

#include <vector>

namespace ausroll::adaptivity
{
  using namespace dealii;

  /** `Indicators = contact`. */
  class ContactIndicator : public IndicatorBase<ContactIndicator>
  {
  public:
    template <int dim>
    void mark_cells(const IndicatorInput<dim> &in, CellFlags &flags) const
    {
      if (!in.die_distance)
        return;
      const AdaptivityParameters &parameters = in.parameters;
      // Deformed cell centre from the displacement at the reference centre.
      Point<dim> unit_centre;
      for (unsigned int d = 0; d < dim; ++d)
        unit_centre[d] = 0.5;
      const Quadrature<dim> centre(unit_centre);
      FEValues<dim>         fe_values(
          in.mapping, in.dof_handler.get_fe(), centre, update_values | update_quadrature_points);
      std::vector<Tensor<1, dim>>      u(1);
      const FEValuesExtractors::Vector displacement(0);
      for (const auto &cell : in.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[displacement].get_function_values(in.solution, u);
          const Point<dim> x = fe_values.quadrature_point(0) + u[0];
          const double     d = in.die_distance(x);
          const double     size = cell->diameter();
          const unsigned   k = cell->active_cell_index();
          if (d < parameters.contact_band + 0.5 * size)
            flags.refine[k] = true;
          const double coarsening_distance = parameters.coarsening_distance > 0.
                                                 ? parameters.coarsening_distance + size
                                                 : 2. * (parameters.contact_band + size);
          if (d < coarsening_distance)
            flags.coarsen[k] = false;
          if (parameters.fine_contact_band > 0.)
          {
            if (!(d < parameters.fine_contact_band + 0.5 * size))
              flags.level_cap[k] = parameters.max_level - 1;
            if (!(d < 2. * (parameters.fine_contact_band + size)))
              flags.coarsen_to_cap[k] = true;
          }
        }
    }
  };
} // namespace ausroll::adaptivity

AUSROLL_REGISTER_REFINEMENT_INDICATOR(ausroll::adaptivity::ContactIndicator,
                                      "contact",
                                      "cells near a die now and at the next step")
