/**
 * @file generalized_plane_strain.h
 * Postprocessor of generalized plane strain: the out-of-plane stretch and the axial force.
 */
#pragma once

#include <ausroll/io/postprocess/interface.h>

namespace ausroll::io::postprocess
{
  /**
   * History columns of a generalized plane strain run (`Model/Planar model = generalized plane
   * strain` only): `stretch_z`, the out-of-plane stretch lambda = F_zz of the section
   * (dimensionless; the axial strain is lambda - 1 in small strain, ln lambda logarithmic), and
   * `axial_force`, N = int sigma_zz da over the deformed section at the last assembly (N; the
   * force on the whole section, `Model/Axial force` at equilibrium).
   */
  template <int dim>
  class GeneralizedPlaneStrainColumns : public Postprocessor<dim>
  {
  public:
    std::string name() const override { return "generalized plane strain"; }

    void execute(const PostprocessInput<dim> &input, HistoryRow &row) const override;

    Unit unit(const std::string &name) const override;
  };
} // namespace ausroll::io::postprocess
