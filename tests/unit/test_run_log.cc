/**
 * @file test_run_log.cc
 * The ETA of the step lines (io::EtaEstimator) and the peak die forces of the run summary
 * (io::RunTotals), on made-up progress whose true remaining time is known.
 */
#include <ausroll/io/run_log.h>

#include <gtest/gtest.h>

using ausroll::io::EtaEstimator;
using ausroll::io::RunTotals;

// Steps of 10 % of the load: the first five cost 1 s each, the next ones 3 s (the contact zone
// has formed). After 6 steps (60 %, 8 s) the remaining 4 steps take 12 s; the run-average rate
// (8 s / 0.6) promises 5.3 s, the recent rate (the last third of the load done, at least the last
// 3 steps: 0.3 in 5 s) 0.4 * 5 / 0.3 = 6.7 s, closer. After 8 steps (14 s) the recent window
// (steps 6 to 8: 0.3 in 9 s) gives 0.2 * 9 / 0.3 = 6 s, the true remainder.
TEST(EtaEstimator, FollowsTheRecentCostWhenStepsGrowDearer)
{
  EtaEstimator eta;
  eta.start(0., 0.);
  double elapsed = 0.;
  for (unsigned int k = 1; k <= 6; ++k)
  {
    elapsed += k <= 5 ? 1. : 3.;
    eta.add(0.1 * k, elapsed);
  }
  EXPECT_NEAR(eta.eta(), 0.4 * 5. / 0.3, 1e-12);
  EXPECT_GT(eta.eta(), 0.4 * 8. / 0.6); // more than the run average promises
  for (unsigned int k = 7; k <= 8; ++k)
  {
    elapsed += 3.;
    eta.add(0.1 * k, elapsed);
  }
  EXPECT_NEAR(eta.eta(), 6., 1e-12);
}

// Steady cost: the ETA is the linear extrapolation (both rates agree); a resumed run (start at
// 50 %) measures only its own steps; no step yet: 0.
TEST(EtaEstimator, SteadyCostAndResumedRun)
{
  EtaEstimator eta;
  EXPECT_EQ(eta.eta(), 0.);
  eta.start(0.5, 2.);
  EXPECT_EQ(eta.eta(), 0.);
  for (unsigned int k = 1; k <= 5; ++k)
    eta.add(0.5 + 0.05 * k, 2. + 1. * k); // 1 s per 5 %
  EXPECT_NEAR(eta.eta(), 0.25 / 0.05 * 1., 1e-12);
}

TEST(RunTotals, PeakForcePerDieAndItsTime)
{
  RunTotals totals;
  totals.record_force(1, "lower", 5., 0.1);
  totals.record_force(0, "upper", 2., 0.1);
  totals.record_force(1, "lower", 7., 0.2);
  totals.record_force(1, "lower", 6., 0.3);
  totals.record_force(0, "upper", 0., 0.3);
  ASSERT_EQ(totals.peak_force.size(), 2u);
  EXPECT_EQ(totals.die_names[0], "upper");
  EXPECT_EQ(totals.peak_force[0], 2.);
  EXPECT_EQ(totals.peak_time[0], 0.1);
  EXPECT_EQ(totals.peak_force[1], 7.);
  EXPECT_EQ(totals.peak_time[1], 0.2);
}
