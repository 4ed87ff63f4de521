/**
 * The adaptive step control of the load stepper (`Loading/Step control = adaptive`,
 * LoadingParameters::step_factor): the exact factors of its rules for the default targets
 * (6 Newton iterations, 4 contact status changes, growth 1.5, smallest factor 0.25).
 */
#include <ausroll/solver/loading_parameters.h>

#include <gtest/gtest.h>

namespace
{
  using ausroll::solver::LoadingParameters;

  TEST(StepControl, GrowsOnlyAfterEasySteps)
  {
    const LoadingParameters p;
    EXPECT_DOUBLE_EQ(p.step_factor(2, 0), 1.5); // easy: <= half of both targets
    EXPECT_DOUBLE_EQ(p.step_factor(3, 2), 1.5);
    EXPECT_DOUBLE_EQ(p.step_factor(4, 0), 1.); // neither easy nor hard: keep
    EXPECT_DOUBLE_EQ(p.step_factor(3, 3), 1.); // easy Newton, but contact busy: keep
    EXPECT_DOUBLE_EQ(p.step_factor(6, 4), 1.); // at the targets: keep
  }

  TEST(StepControl, ShrinksByTargetOverActual)
  {
    const LoadingParameters p;
    EXPECT_DOUBLE_EQ(p.step_factor(12, 0), 0.5);  // 6 / 12
    EXPECT_DOUBLE_EQ(p.step_factor(3, 8), 0.5);   // 4 / 8
    EXPECT_DOUBLE_EQ(p.step_factor(8, 16), 0.25); // min(6/8, 4/16)
    EXPECT_DOUBLE_EQ(p.step_factor(60, 0), 0.25); // not below Minimum step factor
  }

  TEST(StepControl, StatusChangesIgnoredWhenTargetIsZero)
  {
    LoadingParameters p;
    p.target_status_changes = 0;
    EXPECT_DOUBLE_EQ(p.step_factor(2, 100), 1.5);
    EXPECT_DOUBLE_EQ(p.step_factor(9, 100), 6. / 9.);
  }
} // namespace
