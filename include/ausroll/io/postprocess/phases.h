/**
 * @file phases.h
 * Postprocessor of the phase state (`Phases/Enabled`).
 */
#pragma once

#include <ausroll/io/postprocess/interface.h>

namespace ausroll::io::postprocess
{
  /**
   * History columns (after the temperature's): `martensite_min`, `martensite_max`,
   * `martensite_mean` — smallest and largest martensite volume fraction of the material points
   * and their mean over the reference mesh (each cell's measure shared evenly among its points;
   * 2D: the cross-section) (dimensionless; the rest is austenite). VTU cell fields
   * (cell averages of the points): `martensite_fraction` and `carbon_content` (wt%). With
   * bainite kinetics (`Phases/Bainite start times`) also `bainite_min`, `bainite_max`,
   * `bainite_mean` and the VTU field `bainite_fraction`.
   */
  template <int dim>
  class PhaseFractions : public Postprocessor<dim>
  {
  public:
    /** With @p bainite: the bainite columns and field too. */
    explicit PhaseFractions(const bool bainite = false)
        : with_bainite(bainite)
    {
    }

    std::string name() const override { return "phases"; }

    void execute(const PostprocessInput<dim> &input, HistoryRow &row) const override;

    void cell_fields(const PostprocessInput<dim> &input,
                     std::vector<CellField>      &fields) const override;

    Unit unit(const std::string &name) const override;

  private:
    bool with_bainite; ///< bainite kinetics on
  };
} // namespace ausroll::io::postprocess
