/**
 * @file die_forces.h
 * Per-die history columns: force on the workpiece, pose, contact nodes and extent, and the
 * rolling columns of dies with `Motion/Type = rolling`.
 */
#pragma once

#include <ausroll/contact/motion/rolling.h>
#include <ausroll/io/postprocess/interface.h>

#include <deal.II/base/tensor.h>

namespace ausroll::io::postprocess
{
  /**
   * History columns of every die of `Contact` in order, prefix `die_<Name>_` (`Contact/Die N/
   * Name`): `force_x`, `force_y` (3D: and `force_z`; the force of the die on the workpiece, N;
   * 2D: for `Model/Thickness`), `x`, `y` (3D: and `z`; mm), `angle` (deg; the die pose: position
   * of its reference point and rotation in degrees), `stick_nodes`, `slip_nodes` (counts, 1),
   * `contact_length` (mm; extent of the closed nodes' die coordinate s, along the die
   * surface) and `contact_width` (mm; extent of the closed nodes' current positions along the
   * die-frame x axis: for a die pressed along y the contact width, the half-width a in a half
   * model with the symmetry axis at x = 0). A rolling die adds, right after its block, the
   * columns of rolling_columns() (3D: with `force_axial` and `torque`).
   */
  template <int dim>
  class DieForces : public Postprocessor<dim>
  {
  public:
    std::string name() const override { return "die forces"; }
    void        execute(const PostprocessInput<dim> &input, HistoryRow &row) const override;
    Unit        unit(const std::string &column) const override;
  };

  /**
   * Columns of a die with `Motion/Type = rolling`, appended to @p row with @p prefix
   * (`die_<Name>_`): `revolution` theta_G (degrees, in the die's direction of revolution), `feed`
   * f = a_0 - a(t) (mm), and the die's force on the workpiece @p force resolved along the line of
   * centres (N): `force_radial` (along e_r from the workpiece centre to the die centre: negative
   * when the die presses), `force_tangential` (along e_t = k x e_r, counter-clockwise) and
   * `force_magnitude` |F|.
   */
  void rolling_columns(const contact::RollingMotion<2> &rolling,
                       const double                     time,
                       const dealii::Tensor<1, 2>      &force,
                       const std::string               &prefix,
                       HistoryRow                      &row);

  /**
   * 3D columns of a die with `Motion/Type = rolling` (workpiece axis a = `Motion/Rolling/Axis`):
   * `revolution`, `feed` as in 2D; the force @p force of the die on the workpiece (N) along
   * `force_radial` (e_r: from the workpiece axis to the die centre, orthogonal to a),
   * `force_tangential` (e_t = a x e_r), `force_axial` (a), `force_magnitude` |F|; and `torque`
   * = a . @p moment, the moment of the die's nodal forces on the workpiece about the die axis
   * through the die centre (N mm; the die receives the opposite torque).
   */
  void rolling_columns(const contact::RollingMotion<3> &rolling,
                       const double                     time,
                       const dealii::Tensor<1, 3>      &force,
                       const dealii::Tensor<1, 3>      &moment,
                       const std::string               &prefix,
                       HistoryRow                      &row);
} // namespace ausroll::io::postprocess
