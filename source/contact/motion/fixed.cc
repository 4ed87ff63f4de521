#include <ausroll/contact/motion/fixed.h>

namespace ausroll::contact
{
  using dealii::Point;
  using dealii::Tensor;

  // ------------------------------------------------------------------ FixedPose

  template <int dim>
  FixedPose<dim>::FixedPose(const DiePose<dim> &pose)
      : fixed(pose)
  {
  }

  template <int dim>
  DiePose<dim> FixedPose<dim>::pose(const double) const
  {
    return fixed;
  }

  template <int dim>
  Tensor<1, dim> FixedPose<dim>::velocity(const double, const Point<dim> &) const
  {
    return Tensor<1, dim>();
  }

  template <int dim>
  double FixedPose<dim>::angular_velocity(const double) const
  {
    return 0.0;
  }

  std::unique_ptr<DieMotion<2>> FixedMotionParameters::create_2d(const std::string &) const
  {
    return std::make_unique<FixedPose<2>>();
  }

  std::unique_ptr<DieMotion<3>> FixedMotionParameters::create_3d(const std::string &) const
  {
    return std::make_unique<FixedPose<3>>();
  }

  template class FixedPose<2>;
  template class FixedPose<3>;
} // namespace ausroll::contact

AUSROLL_REGISTER_DIE_MOTION(ausroll::contact::FixedMotionParameters,
                            "fixed",
                            "",
                            "the die does not move")
