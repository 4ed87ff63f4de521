/**
 * The adaptive step control of the load stepper (`Loading/Step control = adaptive`,
 * AdaptiveStepControl::step_factor): the exact factors of its rules for the default targets
 * (4 Newton iterations, 4 contact status changes, growth 1.5, smallest factor 0.25); the step
 * controls are registered with their subsections.
 */
#include <ausroll/solver/loading_parameters.h>
#include <ausroll/solver/step_controls/adaptive.h>

#include <deal.II/base/parameter_handler.h>

#include <gtest/gtest.h>

namespace
{
  using ausroll::solver::AdaptiveParameters;
  using ausroll::solver::AdaptiveStepControl;
  using ausroll::solver::LoadingParameters;

  TEST(StepControl, DefaultTargets)
  {
    const AdaptiveParameters p;
    EXPECT_EQ(p.target_newton_iterations, 4u);
    EXPECT_EQ(p.target_status_changes, 4u);
    EXPECT_EQ(LoadingParameters().step_growth_factor, 1.5);
  }

  TEST(StepControl, GrowsOnlyAfterEasySteps)
  {
    const AdaptiveStepControl p(AdaptiveParameters(), 1.5);
    EXPECT_DOUBLE_EQ(p.step_factor(2, 0), 1.5); // easy: <= half of both targets
    EXPECT_DOUBLE_EQ(p.step_factor(2, 2), 1.5);
    EXPECT_DOUBLE_EQ(p.step_factor(3, 0), 1.); // neither easy nor hard: keep
    EXPECT_DOUBLE_EQ(p.step_factor(2, 3), 1.); // easy Newton, but contact busy: keep
    EXPECT_DOUBLE_EQ(p.step_factor(4, 4), 1.); // at the targets: keep
  }

  TEST(StepControl, ShrinksByTargetOverActual)
  {
    const AdaptiveStepControl p(AdaptiveParameters(), 1.5);
    EXPECT_DOUBLE_EQ(p.step_factor(8, 0), 0.5);   // 4 / 8
    EXPECT_DOUBLE_EQ(p.step_factor(2, 8), 0.5);   // 4 / 8
    EXPECT_DOUBLE_EQ(p.step_factor(5, 10), 0.4);  // min(4/5, 4/10)
    EXPECT_DOUBLE_EQ(p.step_factor(60, 0), 0.25); // not below Minimum step factor
  }

  TEST(StepControl, StatusChangesIgnoredWhenTargetIsZero)
  {
    AdaptiveParameters a;
    a.target_status_changes = 0;
    const AdaptiveStepControl p(a, 1.5);
    EXPECT_DOUBLE_EQ(p.step_factor(2, 100), 1.5);
    EXPECT_DOUBLE_EQ(p.step_factor(9, 100), 4. / 9.);
  }

  // The step controls are registered (solver/step_controls/, one file each): the `Step control`
  // selection lists them in name order, `Loading/Adaptive` reaches the rule's parameters, and an
  // old `Loading/Target Newton iterations` names its new place.
  TEST(StepControl, RegisteredWithTheirSubsections)
  {
    EXPECT_EQ(ausroll::solver::StepControlRegistry::instance().names(),
              (std::vector<std::string>{"adaptive", "halving"}));
    dealii::ParameterHandler prm;
    LoadingParameters::declare_parameters(prm);
    prm.parse_input_from_string("subsection Loading\n"
                                "  set Step control = adaptive\n"
                                "  subsection Adaptive\n"
                                "    set Target Newton iterations = 6\n"
                                "    set Minimum step factor = 0.5\n"
                                "  end\n"
                                "end\n");
    LoadingParameters loading;
    loading.parse_parameters(prm);
    EXPECT_EQ(loading.step_control, "adaptive");
    const auto *adaptive
        = dynamic_cast<const AdaptiveParameters *>(loading.step_control_parameters.get());
    ASSERT_NE(adaptive, nullptr);
    EXPECT_EQ(adaptive->target_newton_iterations, 6u);
    EXPECT_EQ(adaptive->target_status_changes, 4u);
    EXPECT_EQ(adaptive->minimum_step_factor, 0.5);
    EXPECT_EQ(LoadingParameters::moved_entries().at("Loading/Target Newton iterations"),
              "`Loading/Adaptive/Target Newton iterations`");
  }
} // namespace
