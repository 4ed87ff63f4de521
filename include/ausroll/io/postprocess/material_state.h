/**
 * @file material_state.h
 * What the material points say: the admissibility check of history.csv and the cell averages of
 * stress and plastic strain in the VTU output.
 */
#pragma once

#include <ausroll/io/postprocess/interface.h>

namespace ausroll::io::postprocess
{
  /**
   * History column `yield_excess`: max(0, largest yield-function value of the committed states)
   * / `Material/Yield stress`. Stays at round-off level unless something (e.g. a mesh transfer)
   * breaks admissibility.
   */
  template <int dim>
  class YieldExcess : public Postprocessor<dim>
  {
  public:
    /** Relative to @p yield_stress = `Material/Yield stress`. */
    explicit YieldExcess(const double yield_stress);
    std::string name() const override { return "yield excess"; }
    void        execute(const PostprocessInput<dim> &input, HistoryRow &row) const override;

  private:
    double yield_stress;
  };

  /**
   * VTU cell fields: the averages over the cell's quadrature points of the committed Cauchy
   * stress `stress_xx`, `stress_yy`, `stress_zz`, `stress_xy`, of `von_mises_stress` and
   * `equivalent_plastic_strain`; then `subdomain` (MPI rank owning the cell) and `level`
   * (refinement level).
   */
  template <int dim>
  class CellAverages : public Postprocessor<dim>
  {
  public:
    std::string name() const override { return "cell averages"; }
    void        cell_fields(const PostprocessInput<dim> &input,
                            std::vector<CellField>      &fields) const override;
  };
} // namespace ausroll::io::postprocess
