/**
 * @file monitor_points.h
 * Displacements at named points (`Postprocess/Monitor points`).
 */
#pragma once

#include <ausroll/io/postprocess/interface.h>

#include <deal.II/base/point.h>

namespace ausroll::io::postprocess
{
  /**
   * History columns `<name>_ux`, `<name>_uy` (`_uz` in 3D; length, mm): the displacement (FE
   * interpolation)
   * at each point of `Postprocess/Monitor points` = "name: x, y; ..." (reference coordinates),
   * in the order given. initialize() locates the points (after every mesh change) and throws
   * InputError naming the entry if a point lies outside the workpiece.
   */
  template <int dim>
  class MonitorPoints : public Postprocessor<dim>
  {
  public:
    /** Points of @p specification (`Postprocess/Monitor points`). */
    explicit MonitorPoints(const std::string &specification);
    std::string name() const override { return "monitor points"; }
    void        initialize(const PostprocessInput<dim> &input) override;
    void        execute(const PostprocessInput<dim> &input, HistoryRow &row) const override;
    Unit        unit(const std::string &column) const override
    {
      (void)column;
      return {"length", "mm"};
    }

  private:
    /** A monitored point: name, position, and where it lives (on its owning rank). */
    struct Point
    {
      std::string                                            name;
      dealii::Point<dim>                                     position;
      bool                                                   local = false;
      typename dealii::DoFHandler<dim>::active_cell_iterator cell;
      dealii::Point<dim>                                     unit_point;
    };
    std::string        specification;
    std::vector<Point> points;
  };
} // namespace ausroll::io::postprocess
