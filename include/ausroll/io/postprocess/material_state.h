/**
 * @file material_state.h
 * What the material points say: the admissibility check of history.csv and the cell averages of
 * stress and plastic strain in the VTU output.
 */
#pragma once

#include <ausroll/io/postprocess/interface.h>
#include <ausroll/material/material_state.h>

#include <deal.II/base/symmetric_tensor.h>

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace ausroll::io::postprocess
{
  /**
   * The strain tensor written to VTU and line probes (dimensionless): for small-strain
   * kinematics (@p small_strain) the infinitesimal strain sym(F) - I, otherwise the logarithmic
   * (Hencky) strain 1/2 ln(F F^T) of the current configuration; F the committed deformation
   * gradient of @p state (plane strain: F_zz = 1, so strain_zz = 0; plane stress: F_zz of the
   * thickness change). Equal to first order for small strains.
   */
  dealii::SymmetricTensor<2, 3> strain_tensor(const material::MaterialState &state,
                                              const bool                     small_strain);

  /**
   * Names and (i, j) indices of the tensor components written for dimension @p dim: 2D `xx`,
   * `yy`, `zz`, `xy`; 3D also `xz`, `yz` (2D: those are zero in plane strain, plane stress and
   * axisymmetry, so they are not written).
   */
  template <int dim>
  std::vector<std::pair<std::string, std::array<unsigned int, 2>>> tensor_components();

  /**
   * History column `yield_excess`: max(0, largest yield-function value of the committed states)
   * / `Material/Yield stress` (dimensionless, 1). Stays at round-off level unless something (e.g. a
   * mesh transfer) breaks admissibility.
   */
  template <int dim>
  class YieldExcess : public Postprocessor<dim>
  {
  public:
    /** Relative to @p yield_stress = `Material/Yield stress`. */
    explicit YieldExcess(const double yield_stress);
    std::string name() const override { return "yield excess"; }
    void        execute(const PostprocessInput<dim> &input, HistoryRow &row) const override;
    Unit        unit(const std::string &column) const override
    {
      (void)column;
      return {"dimensionless", "1"};
    }

  private:
    double yield_stress;
  };

  /**
   * VTU cell fields: the averages over the cell's quadrature points of the committed Cauchy
   * stress `stress_xx`, `stress_yy`, `stress_zz`, `stress_xy` (MPa), of `von_mises_stress` (MPa)
   * and `equivalent_plastic_strain` (1); then `subdomain` (MPI rank owning the cell) and `level`
   * (refinement level); then, in 3D, `stress_xz`, `stress_yz` (MPa); then the strain tensor
   * (strain_tensor(), dimensionless) `strain_xx`, `strain_yy`, `strain_zz`, `strain_xy` (3D:
   * and `strain_xz`, `strain_yz`).
   */
  template <int dim>
  class CellAverages : public Postprocessor<dim>
  {
  public:
    std::string name() const override { return "cell averages"; }
    void        cell_fields(const PostprocessInput<dim> &input,
                            std::vector<CellField>      &fields) const override;
    Unit        unit(const std::string &name) const override;
  };
} // namespace ausroll::io::postprocess
