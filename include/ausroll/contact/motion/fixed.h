/**
 * @file fixed.h
 * Die motion `fixed` (no subsection): the die does not move.
 */
#pragma once

#include <ausroll/contact/die_motion.h>

#include <memory>
#include <string>

namespace ausroll::contact
{
  /** A die that does not move: the same pose at all times (identity by default). */
  template <int dim>
  class FixedPose : public DieMotion<dim>
  {
  public:
    /** Die held at @p pose. */
    explicit FixedPose(const DiePose<dim> &pose = DiePose<dim>());

    /** The fixed pose. */
    DiePose<dim> pose(double t) const override;

    /** Zero. */
    dealii::Tensor<1, dim> velocity(double t, const dealii::Point<dim> &X) const override;

    /** Zero. */
    double angular_velocity(double t) const override;

  private:
    /** The pose. */
    DiePose<dim> fixed;
  };

  /** `Motion/Type = fixed`: no entries; the die stays in its die coordinates. */
  struct FixedMotionParameters : public MotionParameters
  {
    /** No entries. */
    static void declare_parameters(dealii::ParameterHandler &) {}
    void parse(dealii::ParameterHandler &, const std::string &, const std::string &) override {}
    std::unique_ptr<DieMotion<2>> create_2d(const std::string &path) const override;
    std::unique_ptr<DieMotion<3>> create_3d(const std::string &path) const override;
  };
} // namespace ausroll::contact
