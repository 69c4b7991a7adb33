// The decision time per agent in `canopy reproduce` (issue 54): the summary of call times against
// numbers worked by hand, the count of timed calls against the scenario's clock, and how the
// report words the learned planner against SMA-NBO.
#include <gtest/gtest.h>

#include "analysis/decision_time.h"
#include "analysis/report_learned.h"
#include "spec/loader.h"

namespace canopy::analysis {
namespace {

TEST(DecisionTime, MeanMedianPercentileAndIntervalByHand) {
  // Trial A: 1, 2, 3 µs (mean 2); trial B: 4, 6 µs (mean 5); trial C: 10 µs (mean 10).
  const DecisionTime t =
      summariseDecisionTimes({{1e-6, 2e-6, 3e-6}, {4e-6, 6e-6}, {}, {10e-6}});
  EXPECT_EQ(t.trials, 3);  // the empty trial has no calls and does not count
  EXPECT_EQ(t.calls, 6);
  EXPECT_NEAR(t.mean_us.value, 17.0 / 3.0, 1e-9);  // each trial weighs the same
  // Sorted 1 2 3 4 6 10: median (3 + 4)/2; 90th percentile nearest rank ⌈5.4⌉ = 6th → 10; max 10.
  EXPECT_NEAR(t.median_us, 3.5, 1e-9);
  EXPECT_NEAR(t.p90_us, 10.0, 1e-9);
  EXPECT_NEAR(t.max_us, 10.0, 1e-9);
  // Trial means 2, 5, 10: mean 17/3, s² = ((−11/3)² + (−2/3)² + (13/3)²)/2 = 49/3, s/√3 = 7/3,
  // t_{0.975, 2} = 4.302653: half width 10.03952; the low end (−4.37) cut at 0.
  EXPECT_NEAR(t.mean_us.ci.high, 17.0 / 3.0 + 10.03952, 1e-4);
  EXPECT_EQ(t.mean_us.ci.low, 0.0);
}

TEST(DecisionTime, OddCountMedianAndNoCalls) {
  const DecisionTime t = summariseDecisionTimes({{5e-6, 1e-6, 3e-6}});
  EXPECT_NEAR(t.median_us, 3.0, 1e-9);
  EXPECT_NEAR(t.p90_us, 5.0, 1e-9);  // ⌈2.7⌉ = 3rd smallest
  EXPECT_FALSE(t.mean_us.ci.bounded());  // one trial bounds no interval
  EXPECT_FALSE(summariseDecisionTimes({}).timed());
  EXPECT_EQ(decisionTimeText(DecisionTime{}), "—");
}

TEST(DecisionTime, TimesEveryAgentAtEveryEpoch) {
  // Trajectory Handover: 12 s, a decision every 1 s from t = 0 (k = 0, 5, …, 60: 13 epochs), two
  // UAVs: 26 calls per trial.
  spec::LoadOptions options;
  options.overrides = {"planner.algorithm=learned"};
  const spec::ScenarioSpec spec = spec::loadScenario("trajectory_handover", options);
  const DecisionTime t = timeDecisions(spec, {11, 12});
  EXPECT_EQ(t.trials, 2);
  EXPECT_EQ(t.calls, 2 * 13 * 2);
  EXPECT_GT(t.median_us, 0.0);
  EXPECT_LE(t.median_us, t.p90_us);
  EXPECT_LE(t.p90_us, t.max_us);
}

TEST(DecisionTime, TextKeepsTheUnitOfTheMean) {
  DecisionTime fast;
  fast.calls = 10;
  fast.mean_us = {4.8, {4.1, 5.5}, 5};
  EXPECT_EQ(decisionTimeText(fast), "4.8 µs [4.1, 5.5]");
  DecisionTime slow = fast;
  slow.mean_us = {3900.0, {3120.0, 4710.0}, 5};
  EXPECT_EQ(decisionTimeText(slow), "3.90 ms [3.12, 4.71]");
}

TEST(LearnedBehaviours, KeptOnlyWhenTheIntervalsOverlap) {
  const Estimate sma = proportion(20, 20);  // [83.9, 100] %
  EXPECT_EQ(keptText(sma, proportion(4, 20)), "**lost**");                        // [8.1, 41.6] %
  EXPECT_EQ(keptText(sma, proportion(18, 20)), "kept (the intervals overlap)");  // [69.9, 97.2] %
  EXPECT_EQ(keptText(proportion(0, 20), proportion(20, 20)), "higher than SMA-NBO");
}

// The report's table: each timed configuration's figures and its ratio to the learned planner's
// in the same setting; no section when --timing-trials is 0.
TEST(DecisionTime, ReportTableAndRatioToLearned) {
  ExperimentResult r;
  r.experiment.scenario = "some_timed_study";  // no paper row: only the timing table reads it
  r.analysis.specs.emplace_back().uavs.emplace_back();  // the configuration section reads one
  for (const char* planner : {"sma", "learned"}) {
    ConfigStatistics& s = r.analysis.configs.emplace_back();
    s.point = {std::string("planner=\"") + planner + "\"", "planner.horizon=5"};
    s.states = {"M*"};
  }
  DecisionTime sma, learned;
  sma.trials = learned.trials = 5;
  sma.calls = learned.calls = 130;
  sma.mean_us = {8000.0, {7000.0, 9000.0}, 5};
  sma.median_us = 3000.0;
  learned.mean_us = {4.0, {3.0, 5.0}, 5};
  learned.median_us = 3.0;
  r.decision_times = {sma, learned};
  ReportContext ctx;
  ctx.timing_trials = 5;
  const std::string md = reportMarkdown({r}, ctx);
  // 8000 / 4 = 2000 by the means, 3000 / 3 = 1000 by the medians.
  EXPECT_NE(md.find("| some_timed_study | H = 5 | SMA-NBO | 5 | 130 | 8.00 ms [7.00, 9.00] | "
                    "3.00 ms |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| 2000× / 1000× |"), std::string::npos);
  EXPECT_NE(md.find("| some_timed_study | H = 5 | learned (imitates SMA-NBO) | 5 | 130 | "
                    "4.0 µs [3.0, 5.0] | 3.0 µs |"),
            std::string::npos);
  ctx.timing_trials = 0;
  EXPECT_EQ(reportMarkdown({r}, ctx).find("## Decision time per agent"), std::string::npos);
}

}  // namespace
}  // namespace canopy::analysis
