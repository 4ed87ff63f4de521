/**
 * The adaptive step control of the load stepper (`Loading/Step control = adaptive`,
 * LoadingParameters::step_factor): the exact factors of its rules for the default targets
 * (4 Newton iterations, 4 contact status changes, growth 1.5, smallest factor 0.25).
 */
#include <ausroll/solver/loading_parameters.h>

#include <gtest/gtest.h>

namespace
{
  using ausroll::solver::LoadingParameters;

  TEST(StepControl, DefaultTargets)
  {
    const LoadingParameters p;
    EXPECT_EQ(p.target_newton_iterations, 4u);
    EXPECT_EQ(p.target_status_changes, 4u);
  }

  TEST(StepControl, GrowsOnlyAfterEasySteps)
  {
    const LoadingParameters p;
    EXPECT_DOUBLE_EQ(p.step_factor(2, 0), 1.5); // easy: <= half of both targets
    EXPECT_DOUBLE_EQ(p.step_factor(2, 2), 1.5);
    EXPECT_DOUBLE_EQ(p.step_factor(3, 0), 1.); // neither easy nor hard: keep
    EXPECT_DOUBLE_EQ(p.step_factor(2, 3), 1.); // easy Newton, but contact busy: keep
    EXPECT_DOUBLE_EQ(p.step_factor(4, 4), 1.); // at the targets: keep
  }

  TEST(StepControl, ShrinksByTargetOverActual)
  {
    const LoadingParameters p;
    EXPECT_DOUBLE_EQ(p.step_factor(8, 0), 0.5);   // 4 / 8
    EXPECT_DOUBLE_EQ(p.step_factor(2, 8), 0.5);   // 4 / 8
    EXPECT_DOUBLE_EQ(p.step_factor(5, 10), 0.4);  // min(4/5, 4/10)
    EXPECT_DOUBLE_EQ(p.step_factor(60, 0), 0.25); // not below Minimum step factor
  }

  TEST(StepControl, StatusChangesIgnoredWhenTargetIsZero)
  {
    LoadingParameters p;
    p.target_status_changes = 0;
    EXPECT_DOUBLE_EQ(p.step_factor(2, 100), 1.5);
    EXPECT_DOUBLE_EQ(p.step_factor(9, 100), 4. / 9.);
  }
} // namespace
