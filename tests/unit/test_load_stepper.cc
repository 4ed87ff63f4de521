/**
 * @file test_load_stepper.cc
 * solver::LoadStepper on a model problem without a mesh: a SteppedProblem whose solve converges
 * or fails by a rule of the step size, the predictor ratio and the step number, and which
 * records every call. End time 1 with 4 nominal steps (dt = 0.25; all step sizes below are
 * binary fractions, so the times are exact and compared with ==). Tested: halving cutbacks and
 * the size kept after them, growth back to the nominal step, the retry without the predictor
 * (and the predictor ratio dt / dt_prev), the RunFailure message after too many cutbacks with the
 * last converged state, the Minimum step fraction, the adaptive step control (shrink by target /
 * actual Newton iterations and status changes, growth after easy steps), and a contact strategy
 * that shortens a step.
 */
#include <ausroll/core/exceptions.h>
#include <ausroll/solver/load_stepper.h>
#include <ausroll/solver/step_controls/adaptive.h>

#include <deal.II/base/conditional_ostream.h>

#include <gtest/gtest.h>

#include <functional>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  using namespace ausroll;
  using namespace ausroll::solver;

  /** One solve the stepper asked for. */
  struct Solve
  {
    unsigned int step;      ///< step number (converged steps + 1)
    double       dt;        ///< time - t_start
    double       ratio;     ///< predictor ratio (0: none)
    bool         converged; ///< the outcome
  };

  class MockProblem : public SteppedProblem
  {
  public:
    /** Converged? for (step number, dt, ratio); default: always. */
    std::function<bool(unsigned int, double, double)> converges
        = [](unsigned int, double, double) { return true; };
    /** Newton iterations of a converged solve of a step; default 3. */
    std::function<unsigned int(unsigned int)> iterations = [](unsigned int) { return 3u; };
    /** Status changes reported by accept_step(); default 0. */
    std::function<unsigned int(unsigned int)> status_changes = [](unsigned int) { return 0u; };
    /** end_of_step() decision for (step number, dt); default accept. */
    std::function<contact::StepDecision(unsigned int, double)> decide
        = [](unsigned int, double) { return contact::StepDecision(); };

    std::vector<Solve>    solves;
    std::vector<LoadStep> accepted;
    unsigned int          restarts = 0;
    std::vector<double>   kept; ///< keep_last_converged() times

    void begin_step(const double t) override
    {
      t_start = t;
      EXPECT_EQ(t, accepted.empty() ? 0. : accepted.back().time);
    }
    NewtonResult solve(const double time, const double ratio) override
    {
      const unsigned int step = accepted.size() + 1;
      NewtonResult       r;
      r.converged = converges(step, time - t_start, ratio);
      r.iterations = r.converged ? iterations(step) : 20;
      r.reason = r.converged ? "" : "residual diverged";
      solves.push_back({step, time - t_start, ratio, r.converged});
      return r;
    }
    void         restart_step() override { ++restarts; }
    unsigned int release_after_failure() override
    {
      releases.push_back(accepted.size() + 1);
      released_now = release(accepted.size() + 1);
      return released_now;
    }
    /** Contact statuses release_after_failure() changes at step (number); default none. */
    std::function<unsigned int(unsigned int)> release = [](unsigned int) { return 0u; };
    std::vector<unsigned int>                 releases; ///< step numbers of the calls
    unsigned int                              released_now = 0;
    contact::StepDecision                     end_of_step(const double dt) override
    {
      return decide(accepted.size() + 1, dt);
    }
    std::string keep_last_converged(const double t) override
    {
      kept.push_back(t);
      return "the mesh folds at step 0";
    }
    unsigned int accept_step(const LoadStep &step) override
    {
      accepted.push_back(step);
      return status_changes(step.number);
    }

    /** Times of the accepted steps. */
    std::vector<double> times() const
    {
      std::vector<double> t;
      for (const LoadStep &s : accepted)
        t.push_back(s.time);
      return t;
    }

  private:
    double t_start = 0.;
  };

  LoadingParameters loading()
  {
    LoadingParameters p;
    p.end_time = 1.;
    p.number_of_steps = 4;
    p.max_cutbacks = 6;
    p.step_growth_factor = 1.5;
    return p;
  }

  struct Logs
  {
    std::ostringstream         text, details;
    dealii::ConditionalOStream log{text, true}, detail_log{details, true};
  };
} // namespace

// Steps above 0.1 fail: 0.25 -> 0.125 -> 0.0625 (2 cutbacks); the size that worked is kept
// (0.0625), then grows by 1.5 (0.09375) and is clipped to the nominal grid (0.25 - 0.21875).
TEST(LoadStepper, HalvingCutsBackKeepsTheSizeThatWorkedAndGrows)
{
  Logs        logs;
  LoadStepper stepper(loading(), "out", logs.log, logs.detail_log);
  MockProblem p;
  p.converges = [](unsigned int, double dt, double) { return dt <= 0.1; };
  stepper.run(p, 0., stepper.nominal_step_size(), 0);

  ASSERT_GE(p.solves.size(), 6u);
  const double tried[] = {0.25, 0.125, 0.0625, 0.0625, 0.09375, 0.03125};
  for (unsigned int i = 0; i < 6; ++i)
    EXPECT_EQ(p.solves[i].dt, tried[i]) << "solve " << i;
  EXPECT_EQ(p.accepted[0].cutbacks, 2u);
  EXPECT_EQ(p.accepted[0].time, 0.0625);
  EXPECT_EQ(p.accepted[0].step_size, 0.25); // the size held before the step
  EXPECT_EQ(p.accepted[1].cutbacks, 0u);
  EXPECT_EQ(p.accepted[2].time, 0.21875);
  EXPECT_EQ(p.accepted[3].time, 0.25);                        // on the nominal grid
  EXPECT_EQ(p.restarts, p.solves.size() - p.accepted.size()); // one per failed solve
  // every step number once, in order, and the run ends at exactly t = 1 on the grid
  for (unsigned int i = 0; i < p.accepted.size(); ++i)
  {
    EXPECT_EQ(p.accepted[i].number, i + 1);
    EXPECT_LE(p.accepted[i].time - p.accepted[i].t_start, 0.1);
  }
  EXPECT_EQ(p.accepted.back().time, 1.);
  EXPECT_NE(logs.text.str().find("  step 1 (t = 0.25): residual diverged; cutting back to dt = "
                                 "0.125\n"),
            std::string::npos)
      << logs.text.str();
  EXPECT_EQ(stepper.last_step_size, p.accepted.back().time - p.accepted.back().t_start);
}

// With the predictor the first step has none (no previous step); then ratio = dt / dt_prev. A
// failure with the predictor is retried without it, at the same dt and without a cutback.
TEST(LoadStepper, RetryWithoutPredictorBeforeCuttingBack)
{
  Logs              logs;
  LoadingParameters l = loading();
  l.predictor = Predictor::linear_extrapolation;
  LoadStepper stepper(l, "out", logs.log, logs.detail_log);
  MockProblem p;
  p.converges = [](unsigned int step, double, double ratio) { return step != 2 || ratio == 0.; };
  stepper.run(p, 0., 0.25, 0);

  ASSERT_EQ(p.accepted.size(), 4u);
  ASSERT_EQ(p.solves.size(), 5u);
  EXPECT_EQ(p.solves[0].ratio, 0.); // step 1: no previous step
  EXPECT_EQ(p.solves[1].ratio, 1.); // step 2: 0.25 / 0.25, fails
  EXPECT_FALSE(p.solves[1].converged);
  EXPECT_EQ(p.solves[2].ratio, 0.); // step 2 again, without the predictor, same dt
  EXPECT_EQ(p.solves[2].dt, 0.25);
  EXPECT_EQ(p.solves[3].ratio, 1.); // step 3: with the predictor again
  EXPECT_EQ(p.accepted[1].cutbacks, 0u);
  EXPECT_EQ(p.restarts, 1u);
  EXPECT_NE(logs.text.str().find("  step 2 (t = 0.5): residual diverged; trying again without "
                                 "the predictor"),
            std::string::npos)
      << logs.text.str();
}

// Release after a failure: without the predictor, step 2 fails until the problem has released
// contact statuses (2 nodes at the first failure): solved again at the same dt, no cutback, one
// restart; the release is asked for once per step (step 3 fails at 0.25 with nothing to release
// and is cut back once).
TEST(LoadStepper, ReleaseAfterFailureBeforeCuttingBack)
{
  Logs        logs;
  LoadStepper stepper(loading(), "out", logs.log, logs.detail_log);
  MockProblem p;
  p.release = [](unsigned int step) { return step == 2 ? 2u : 0u; };
  p.converges = [&p](unsigned int step, double dt, double)
  { return step == 2 ? p.released_now > 0 : (step != 3 || dt < 0.25); };
  stepper.run(p, 0., 0.25, 0);

  ASSERT_GE(p.solves.size(), 5u);
  EXPECT_FALSE(p.solves[1].converged); // step 2, then again at the same size
  EXPECT_EQ(p.solves[2].dt, 0.25);
  EXPECT_TRUE(p.solves[2].converged);
  EXPECT_FALSE(p.solves[3].converged); // step 3 at 0.25, then at 0.125
  EXPECT_EQ(p.solves[4].dt, 0.125);
  EXPECT_EQ(p.accepted[1].cutbacks, 0u);
  EXPECT_EQ(p.accepted[2].cutbacks, 1u); // step 3: nothing to release, halved
  EXPECT_EQ(p.releases, (std::vector<unsigned int>{2, 3}));
  EXPECT_EQ(p.restarts, 2u);
  EXPECT_NE(logs.text.str().find("  step 2 (t = 0.5): residual diverged; trying again with 2 "
                                 "freshly closed node(s) slipping"),
            std::string::npos)
      << logs.text.str();
}

// Predictor ratio after a cutback: step 1 (no predictor) converges at 0.125 after one cutback,
// step 2 keeps 0.125 (ratio 0.125 / 0.125 = 1), step 3 grows to 0.1875 (ratio 1.5).
TEST(LoadStepper, PredictorRatioIsStepOverLastStep)
{
  Logs              logs;
  LoadingParameters l = loading();
  l.predictor = Predictor::linear_extrapolation;
  LoadStepper stepper(l, "out", logs.log, logs.detail_log);
  MockProblem p;
  p.converges = [](unsigned int step, double dt, double) { return dt <= (step == 1 ? 0.2 : 1.); };
  stepper.run(p, 0., 0.25, 0);
  ASSERT_GE(p.solves.size(), 4u);
  EXPECT_EQ(p.solves[1].dt, 0.125);
  EXPECT_EQ(p.solves[2].dt, 0.125); // size kept after the cutback
  EXPECT_EQ(p.solves[2].ratio, 1.);
  EXPECT_EQ(p.solves[3].dt, 0.1875); // 0.125 * 1.5
  EXPECT_EQ(p.solves[3].ratio, 1.5); // 0.1875 / 0.125
}

namespace
{
  /** Run @p l on a problem whose step 2 never converges: the stepper cuts step 2 back from
      0.25 to 0.03125 (4 solves) and throws RunFailure with @p message; the last converged
      state (t = 0.25) is kept. */
  void expect_failure_of_step_2_at_dt_0_03125(const LoadingParameters &l,
                                              const std::string       &message)
  {
    Logs        logs;
    LoadStepper stepper(l, "out", logs.log, logs.detail_log);
    MockProblem p;
    p.converges = [](unsigned int step, double, double) { return step == 1; };
    try
    {
      stepper.run(p, 0., 0.25, 0);
      FAIL() << "no RunFailure";
    }
    catch (const RunFailure &e)
    {
      EXPECT_EQ(std::string(e.what()), message);
    }
    ASSERT_EQ(p.accepted.size(), 1u);
    ASSERT_EQ(p.solves.size(), 5u); // step 1, then 0.25, 0.125, 0.0625, 0.03125
    EXPECT_EQ(p.solves.back().dt, 0.03125);
    EXPECT_EQ(p.restarts, 4u);
    ASSERT_EQ(p.kept.size(), 1u);
    EXPECT_EQ(p.kept[0], 0.25);
  }
} // namespace

// A step that never converges: after Maximum cutbacks (3) the last converged state is kept and
// RunFailure names the step, the time of the last try, the reason, the last converged step and
// time, the output directory and the earlier warning.
TEST(LoadStepper, TooManyCutbacksFailWithLastConvergedState)
{
  LoadingParameters l = loading();
  l.max_cutbacks = 3;
  expect_failure_of_step_2_at_dt_0_03125(
      l,
      "load step 2 (t = 0.28125) did not converge after 3 cutbacks: residual diverged. The last "
      "converged state (step 1, t = 0.25) is in out/. Earlier, the mesh folds at step 0");
}

// Minimum step fraction 0.1 (0.025 of the nominal 0.25), Maximum cutbacks 20: the same step is
// cut 0.25 -> 0.125 -> 0.0625 -> 0.03125, whose half is below 0.025, so the run stops there (3
// cutbacks, not 20) with the last converged state and a message naming the entry.
TEST(LoadStepper, MinimumStepFractionEndsTheRunInsteadOfCreeping)
{
  LoadingParameters l = loading();
  l.max_cutbacks = 20;
  l.minimum_step_fraction = 0.1;
  Logs logs;
  EXPECT_EQ(LoadStepper(l, "out", logs.log, logs.detail_log).minimum_step_size(), 0.025);
  expect_failure_of_step_2_at_dt_0_03125(
      l,
      "load step 2 (t = 0.28125) did not converge with dt = 0.03125, and half of it is below "
      "Loading/Minimum step fraction = 0.1 of the nominal step (0.025): residual diverged. The "
      "last converged state (step 1, t = 0.25) is in out/. Earlier, the mesh folds at step 0");
}

// The adaptive step control does not shrink below the minimum: 24 Newton iterations (target 6)
// ask for a quarter of the step at every step, Minimum step fraction 0.5 holds it at 0.125.
TEST(LoadStepper, AdaptiveStepControlStopsAtTheMinimumStep)
{
  Logs              logs;
  LoadingParameters l = loading();
  l.step_control = "adaptive";
  l.minimum_step_fraction = 0.5;
  LoadStepper stepper(l, "out", logs.log, logs.detail_log);
  MockProblem p;
  p.iterations = [](unsigned int) { return 24u; };
  stepper.run(p, 0., 0.25, 0);
  EXPECT_EQ(p.times(), (std::vector<double>{0.25, 0.375, 0.5, 0.625, 0.75, 0.875, 1.}));
  EXPECT_NE(logs.details.str().find("  step control: 24 Newton iterations, 0 contact status "
                                    "changes, 0 cutbacks: next dt = 0.125"),
            std::string::npos)
      << logs.details.str();
}

// Step control = adaptive: 12 Newton iterations (target 6) halve the step, easy steps (<= 3
// iterations, <= 2 status changes) grow it by 1.5 (from the size asked for, not the one clipped
// to the grid), 8 status changes (target 4) halve it; never above the nominal step.
TEST(LoadStepper, AdaptiveStepControlShrinksAndGrows)
{
  Logs              logs;
  LoadingParameters l = loading();
  l.step_control = "adaptive";
  auto adaptive = std::make_shared<ausroll::solver::AdaptiveParameters>();
  adaptive->target_newton_iterations = 6; // 12 iterations halve the step; 2 are easy (<= 3)
  l.step_control_parameters = adaptive;
  LoadStepper stepper(l, "out", logs.log, logs.detail_log);
  MockProblem p;
  p.iterations = [](unsigned int step) { return step == 1 ? 12u : 2u; };
  p.status_changes = [](unsigned int step) { return step == 4 ? 8u : 0u; };
  stepper.run(p, 0., 0.25, 0);
  EXPECT_EQ(p.times(), (std::vector<double>{0.25, 0.375, 0.5, 0.75, 0.875, 1.}));
  EXPECT_EQ(p.solves.size(), 6u);
  EXPECT_NE(logs.details.str().find("  step control: 12 Newton iterations, 0 contact status "
                                    "changes, 0 cutbacks: next dt = 0.125"),
            std::string::npos)
      << logs.details.str();
}

// Adaptive after a cutback: the factor is at most 1 and applies to the size taken.
TEST(LoadStepper, AdaptiveAfterCutbackKeepsTheSizeTaken)
{
  Logs              logs;
  LoadingParameters l = loading();
  l.step_control = "adaptive";
  LoadStepper stepper(l, "out", logs.log, logs.detail_log);
  MockProblem p;
  p.converges = [](unsigned int step, double dt, double) { return step > 1 || dt <= 0.2; };
  p.iterations = [](unsigned int) { return 2u; };
  stepper.run(p, 0., 0.25, 0);
  ASSERT_GE(p.solves.size(), 3u);
  EXPECT_EQ(p.solves[1].dt, 0.125);
  EXPECT_EQ(p.solves[2].dt, 0.125); // easy, but after a cutback: factor 1
  EXPECT_EQ(p.solves[3].dt, 0.1875);
}

namespace
{
  /** A contact strategy's decision that solves step 1 again with half its size if it was a
      full nominal step (0.25), and accepts every other step. */
  contact::StepDecision halve_first_full_step(const unsigned int step, const double dt)
  {
    contact::StepDecision d;
    if (step == 1 && dt == 0.25)
    {
      d.accept = false;
      d.step_factor = 0.5;
    }
    return d;
  }
} // namespace

// A contact strategy that shortens step 1 to half (a status change inside it, load-increment
// ratio): the step is solved again with dt / 2 and accepted there; the run goes on to the grid.
TEST(LoadStepper, ContactStrategyShortensTheStep)
{
  Logs        logs;
  LoadStepper stepper(loading(), "out", logs.log, logs.detail_log);
  MockProblem p;
  p.decide = halve_first_full_step;
  stepper.run(p, 0., 0.25, 0);
  EXPECT_EQ(p.times(), (std::vector<double>{0.125, 0.25, 0.5, 0.75, 1.}));
  EXPECT_EQ(p.accepted[0].cutbacks, 0u);
  EXPECT_EQ(p.restarts, 0u);
}

// The solve count of the run holds the solves of every attempt: step 1 is shortened once by the
// contact strategy (3 solves discarded) and step 2 goes on to the grid (0.125); step 3 fails at
// 0.25 (20 solves, the mock's count of a failure) and is cut back; its accepted attempt takes 5
// solves, every other 3.
TEST(LoadStepper, SolveCountHoldsDiscardedAttempts)
{
  Logs        logs;
  LoadStepper stepper(loading(), "out", logs.log, logs.detail_log);
  MockProblem p;
  p.decide = halve_first_full_step;
  p.converges = [](unsigned int step, double dt, double) { return step != 3 || dt < 0.25; };
  p.iterations = [](unsigned int step) { return step == 3 ? 5u : 3u; };
  stepper.run(p, 0., 0.25, 0);
  const SolveCount &count = stepper.solve_count;
  ASSERT_EQ(count.per_step.size(), p.accepted.size());
  EXPECT_EQ(p.accepted[0].discarded_solves, 3u);
  EXPECT_EQ(p.accepted[1].discarded_solves, 0u);
  EXPECT_EQ(p.accepted[2].discarded_solves, 20u);
  EXPECT_EQ(p.accepted[2].cutbacks, 1u);
  EXPECT_EQ(count.discarded, 23u);
  unsigned long long accepted = 0;
  for (std::size_t i = 0; i < p.accepted.size(); ++i)
  {
    EXPECT_EQ(count.per_step[i], p.accepted[i].result.iterations);
    accepted += p.accepted[i].result.iterations;
  }
  EXPECT_EQ(count.accepted(), accepted);
  EXPECT_EQ(count.median(), 3.);
  // the total of all solve() calls of the mock: 20 for a failure, else its iterations
  unsigned long long all = 0;
  for (const Solve &s : p.solves)
    all += s.converged ? (s.step == 3 ? 5u : 3u) : 20u;
  EXPECT_EQ(count.accepted() + count.discarded, all);
}

TEST(SolveCount, MedianOfEvenAndOddCounts)
{
  SolveCount c;
  EXPECT_EQ(c.median(), 0.);
  c.per_step = {7, 2, 3};
  EXPECT_EQ(c.median(), 3.);
  c.per_step = {7, 2, 3, 4};
  EXPECT_EQ(c.median(), 3.5);
  EXPECT_EQ(c.accepted(), 16u);
}

// Resumed runs continue at their step number and time.
TEST(LoadStepper, ResumesAtGivenStepAndTime)
{
  Logs        logs;
  LoadStepper stepper(loading(), "out", logs.log, logs.detail_log);
  MockProblem p;
  p.accepted.push_back({}); // as if step 1 had been accepted at t = 0.5 (begin_step checks it)
  p.accepted.back().time = 0.5;
  stepper.run(p, 0.5, 0.25, 2);
  ASSERT_EQ(p.accepted.size(), 3u);
  EXPECT_EQ(p.accepted[1].number, 3u);
  EXPECT_EQ(p.accepted[1].t_start, 0.5);
  EXPECT_EQ(p.accepted[2].time, 1.);
}

namespace
{
  /** Three stages over [0, 1]: quench to 0.375 with steps of 0.125, hold to 0.5 on Loading's
      grid (0.25), cooling to 1 with steps of 0.1875 (its grid 0.6875, 0.875, 1.0625: the last
      step is cut at the stage's end). */
  StageParameters three_stages()
  {
    StageParameters s;
    s.stages = {{"quench", 0.375, 0.125, {}}, {"hold", 0.5, 0., {}}, {"cooling", 1., 0.1875, {}}};
    return s;
  }

  /** A stepper through three_stages() with its logs. */
  struct StagedStepper
  {
    Logs                  logs;
    const StageParameters stages = three_stages();
    LoadStepper           stepper{loading(), "out", logs.log, logs.detail_log};
    StagedStepper() { stepper.set_stages(&stages); }
  };
} // namespace

// Stage ends are step ends; each stage steps on its own grid from its own step size (not the
// size the stage before ended with), and the log names each stage where it begins.
TEST(LoadStepper, StagesEndStepsAndSetTheirStepSize)
{
  StagedStepper staged;
  LoadStepper  &stepper = staged.stepper;
  MockProblem   p;
  stepper.run(p, 0., stepper.nominal_step_size(), 0);
  const std::vector<double> expected{0.125, 0.25, 0.375, 0.5, 0.6875, 0.875, 1.};
  EXPECT_EQ(p.times(), expected);
  // a step starting at a stage's end belongs to the next stage
  EXPECT_EQ(staged.stages.stage_at(0.375), 1u);
  EXPECT_EQ(staged.stages.stage_at(0.3), 0u);
  for (const char *line : {"Stage 0 (quench): t = 0 to 0.375, step 0.125\n",
                           "Stage 1 (hold): t = 0.375 to 0.5, step 0.25\n",
                           "Stage 2 (cooling): t = 0.5 to 1, step 0.1875\n"})
    EXPECT_NE(staged.logs.text.str().find(line), std::string::npos) << staged.logs.text.str();
}

// The run's progress counts nominal steps (3 + 0.5 + 2.67 of 6.17 in three_stages()), and the
// set-up checks sample every stage: a stage of one step by its end, the others at most once per
// step and at least twice; without stages the old even grid.
TEST(LoadStepper, StagesProgressAndSampleTimes)
{
  const StageParameters stages = three_stages();
  const double          total = 3. + 0.125 / 0.25 + 0.5 / 0.1875;
  EXPECT_NEAR(stages.progress(0.375, loading()), 3. / total, 1e-14);
  EXPECT_NEAR(stages.progress(0.4375, loading()), 3.25 / total, 1e-14);
  EXPECT_NEAR(stages.progress(1., loading()), 1., 1e-14);
  const std::vector<double> few = stages.sample_times(loading(), 4);
  // quench: 2 (4 * 3 / 6.17 -> 2), hold: 1 (a single step), cooling: 2
  const std::vector<double> expected{0., 0.1875, 0.375, 0.5, 0.75, 1.};
  ASSERT_EQ(few.size(), expected.size());
  for (unsigned int i = 0; i < expected.size(); ++i)
    EXPECT_NEAR(few[i], expected[i], 1e-14) << i;
  const std::vector<double> many = stages.sample_times(loading(), 256);
  EXPECT_EQ(many.size(), 1u + 3u + 1u + 3u); // at most one per step: 3, 1, ceil(2.67) = 3
  const StageParameters     none;
  const std::vector<double> even = none.sample_times(loading(), 256);
  EXPECT_EQ(even.size(), loading().number_of_steps + 1);
  EXPECT_EQ(even.back(), loading().end_time);
  EXPECT_NEAR(none.progress(0.25, loading()), 0.25 / loading().end_time, 1e-15);
}

// After a cutback inside a stage the step-size control works within the stage's nominal step
// (growth back to 0.1875, not to Loading's 0.25), and the next stage starts with its own step.
TEST(LoadStepper, StagesBoundTheStepSizeControl)
{
  StagedStepper staged;
  LoadStepper  &stepper = staged.stepper;
  MockProblem   p;
  // step 5 (the first of the cooling) fails at 0.1875: cut back to 0.09375, then 1.5 times that
  p.converges = [](unsigned int step, double dt, double) { return step != 5 || dt < 0.1; };
  stepper.run(p, 0., stepper.nominal_step_size(), 0);
  // 0.09375 kept after the cutback, then 1.5 times: 0.140625, then 0.2109375 bounded by 0.1875
  const std::vector<double> expected{0.125, 0.25, 0.375, 0.5, 0.59375, 0.6875, 0.828125, 0.875, 1.};
  EXPECT_EQ(p.times(), expected);
  EXPECT_EQ(p.accepted[4].cutbacks, 1u);
  EXPECT_EQ(p.accepted[7].step_size, 0.1875); // the size held before step 8: the stage's step
}

// A resume inside a stage (from a checkpoint) continues on the stage's grid with the stored
// step size and says where it resumed.
TEST(LoadStepper, StagesResumeInsideAStage)
{
  StagedStepper staged;
  LoadStepper  &stepper = staged.stepper;
  MockProblem   p;
  p.accepted.push_back({}); // as if 5 steps had been accepted, the last at t = 0.6875
  p.accepted.back().time = 0.6875;
  stepper.run(p, 0.6875, 0.1875, 5);
  ASSERT_EQ(p.accepted.size(), 3u);
  EXPECT_EQ(p.accepted[1].time, 0.875);
  EXPECT_EQ(p.accepted[2].time, 1.);
  EXPECT_NE(staged.logs.text.str().find("resuming in stage 2 (cooling) at t = 0.6875"),
            std::string::npos)
      << staged.logs.text.str();
}

// The first step of a stage is solved without the predictor (the increment of the stage before
// says nothing of the new conditions: 0.25 / 0.125 would extrapolate it twice), later steps with
// it.
TEST(LoadStepper, StagesStartWithoutThePredictor)
{
  Logs              logs;
  LoadingParameters l = loading();
  l.predictor = Predictor::linear_extrapolation;
  LoadStepper           stepper(l, "out", logs.log, logs.detail_log);
  const StageParameters stages = three_stages();
  stepper.set_stages(&stages);
  MockProblem p;
  stepper.run(p, 0., stepper.nominal_step_size(), 0);
  ASSERT_EQ(p.solves.size(), 7u);
  const std::vector<double> ratios{0., 1., 1., 0., 0., 1., 0.125 / 0.1875};
  for (unsigned int i = 0; i < ratios.size(); ++i)
    EXPECT_EQ(p.solves[i].ratio, ratios[i]) << "solve " << i;
}
