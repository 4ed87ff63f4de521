/**
 * @file die_geometry.h
 * The dies as geometry for ParaView: with every VTU output, each die's analytic surface sampled
 * near the workpiece in its pose at that time, so that the tool is seen beside the workpiece.
 */
#pragma once

#include <ausroll/contact/rigid_surface.h>
#include <ausroll/io/postprocess/interface.h>

#include <array>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace ausroll::io::postprocess
{
  /**
   * With dies and `Output/Write VTU`: `dies_NNNN.vtm` per output (a multiblock data set with one
   * block per die, named by `Contact/Die N/Name`, each in `dies_NNNN_<k>.vtu`) and the time series
   * `dies.pvd` (one entry per output, the same times as solution.pvd; open it beside
   * solution.pvd). Every point is a point of the die's analytic surface
   * (contact::RigidSurface::point_at()) in its pose at the output's time, in global coordinates
   * (mm): 2D dies as poly lines (z = 0), 3D dies as quadrilateral patches. Arrays: point and cell
   * data `die_id` (the die's index N), field data `TIME`.
   *
   * The part drawn: the surface coordinates of the projections of the workpiece's deformed
   * boundary vertices onto the die, widened by a quarter of their range on each side (a
   * periodic coordinate: the shortest arc holding them, or the whole period); 3D: the mantle of
   * an extruded profile (not its end caps). Sampling: adaptive along each surface coordinate
   * (halving an interval while its midpoint lies farther than 2e-4 of the workpiece size from
   * the chord), so that curved parts, fillets and corners are resolved; at most 2000 points per
   * coordinate.
   *
   * Written on rank 0 (the ranges are reduced over all ranks). When a run resumes, the entries of
   * the existing dies.pvd before the first new output are kept.
   */
  template <int dim>
  class DieGeometry : public Postprocessor<dim>
  {
  public:
    /** Writing only with @p write_vtu (`Output/Write VTU`). */
    explicit DieGeometry(const bool write_vtu);
    std::string name() const override { return "die geometry"; }
    void        write_files(const PostprocessInput<dim> &input,
                            const std::string           &directory,
                            const unsigned int           counter) override;

  private:
    bool                                        write_vtu;
    bool                                        first_output = true;
    std::vector<std::pair<double, std::string>> records; ///< (time, .vtm file) of dies.pvd
  };

  /**
   * Surface coordinates (dim - 1 numbers) to sample a surface at: the sorted values along each
   * coordinate a in [lo[a], hi[a]], refined where the curve through @p point_at along that
   * coordinate (at a few fixed values of the other coordinate) deviates from its chords by more
   * than @p tolerance. At most @p max_points values per coordinate (the tolerance is relaxed
   * until they suffice).
   */
  template <int dim>
  std::array<std::vector<double>, dim - 1> sample_coordinates(
      const std::function<dealii::Point<dim>(const std::array<double, dim - 1> &)> &point_at,
      const std::array<double, dim - 1>                                            &lo,
      const std::array<double, dim - 1>                                            &hi,
      const double                                                                  tolerance,
      const unsigned int max_points = 2000);
} // namespace ausroll::io::postprocess
