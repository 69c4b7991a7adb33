// The report's findings computed as values, on hand-built statistics whose answers are worked
// out by hand in the comments.
#include "analysis/findings.h"

#include <gtest/gtest.h>

#include <cmath>

namespace canopy::analysis {
namespace {

ConfigStatistics configWith(std::vector<std::string> point) {
  ConfigStatistics s;
  s.point = std::move(point);
  s.states = {"M0", "M*", "Other"};
  s.dt = 0.2;
  return s;
}

ExperimentResult experiment(const std::string& scenario, std::vector<std::string> targets) {
  ExperimentResult r;
  r.experiment.scenario = scenario;
  spec::ScenarioSpec spec;
  for (const std::string& name : targets) spec.targets.push_back({name, 1, {}});
  r.analysis.specs.push_back(spec);
  return r;
}

TEST(Findings, HorizonCompareTheMeanShareOfColumnsInMStar) {
  ExperimentResult th = experiment("trajectory_handover", {"I"});
  ConfigStatistics h5 = configWith({"planner=\"sma\"", "planner.horizon=5"});
  h5.trial_states = {{0, 1, 1, 1, 1}, {0, 0, 1, 1, 1}};  // in M* at 4/4 and 3/4 of L/4…L
  ConfigStatistics h1 = configWith({"planner=\"sma\"", "planner.horizon=1"});
  h1.trial_states = {{0, 0, 0, 1, 1}, {0, 0, 0, 0, 1}};  // 2/4 and 1/4
  th.analysis.configs = {h5, h1};
  const Findings f = computeFindings({th});
  ASSERT_EQ(f.horizon.size(), 1u);
  EXPECT_EQ(f.horizon[0].planner, "SMA-NBO");
  EXPECT_DOUBLE_EQ(f.horizon[0].h5.value, 0.875);  // (1 + 0.75) / 2
  EXPECT_DOUBLE_EQ(f.horizon[0].h1.value, 0.375);  // (0.5 + 0.25) / 2
  EXPECT_TRUE(f.horizon[0].holds());
}

// Trials of one configuration whose coverage of target 0 is given per trial (target 1 is
// always covered).
ConfigStatistics withTrials(std::vector<std::string> point,
                            const std::vector<std::vector<int>>& coverage_of_I) {
  ConfigStatistics s = configWith(std::move(point));
  s.trials = static_cast<int>(coverage_of_I.size());
  for (const std::vector<int>& c : coverage_of_I)
    s.trial_coverage.push_back({c, std::vector<int>(c.size(), 1)});
  return s;
}

TEST(Findings, ReactionTimesAreTheFirstStepsBelowTheirThresholdsPerDecisionPeriod) {
  ExperimentResult je = experiment("joint_effect", {"I", "II"});
  // Every trial alike: the mean is the trial's own curve, and every resample gives the same
  // crossing, so the interval is that one time.
  const std::vector<int> early = {1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 0, 0};  // below 0.9 from k = 10
  const std::vector<int> late = {1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 0};  // from k = 13
  const std::vector<int> never = std::vector<int>(14, 1);
  je.analysis.configs = {
      withTrials({"planner.occlusion_map=\"a_priori\"", "planner.replan_period=1.0"}, {late, late}),
      withTrials({"planner.occlusion_map=\"dynamic\"", "planner.replan_period=1.0"},
                 {never, never}),
      withTrials({"planner.occlusion_map=\"a_priori\"", "planner.replan_period=0.2"},
                 {early, early}),
      withTrials({"planner.occlusion_map=\"dynamic\"", "planner.replan_period=0.2"}, {late, late})};
  const Findings f = computeFindings({je});
  ASSERT_EQ(f.reaction.size(), 4u);  // per decision period, a-priori then dynamic
  const std::string second = decisionPeriods()[0].label, step = decisionPeriods()[1].label;
  EXPECT_EQ(f.reaction[0].decisions, second);
  EXPECT_EQ(f.reaction[0].map, "a_priori");
  EXPECT_DOUBLE_EQ(*f.reaction[0].onset.time_s, 13 * 0.2);
  EXPECT_DOUBLE_EQ(f.reaction[0].onset.ci.low, 13 * 0.2);
  EXPECT_DOUBLE_EQ(f.reaction[0].onset.ci.high, 13 * 0.2);
  EXPECT_FALSE(f.reaction[1].onset.time_s);  // the dynamic map never leaves I
  EXPECT_DOUBLE_EQ(*f.reaction[2].onset.time_s, 10 * 0.2);
  EXPECT_FALSE(reactsBeforeHiding(f.reaction, second));  // 2.6 s ≥ 2.2 s
  EXPECT_TRUE(reactsBeforeHiding(f.reaction, step));     // 2.0 s < 2.2 s
  EXPECT_TRUE(f.symptoms.reaction_late);                 // judged at decisions every 1 s
  EXPECT_FALSE(dynamicReactsLater(f.reaction, second));  // the dynamic map never gets half-way
  EXPECT_TRUE(*dynamicReactsLater(f.reaction, step));    // half-way 2.6 s after 2.0 s
}

// Two trials, A crossing 0.9 at k = 1 and B at k = 3. Resamples of two, by hand: {A, A} (1/4)
// crosses at k = 1, {B, B} (1/4) at k = 3, and {A, B} (1/2), mean (1, ½, ½, 0, 0), at k = 1:
// onset 0.2 s w.p. ¾ and 0.6 s w.p. ¼, so the 2.5 and 97.5 percentiles are 0.2 and 0.6 s.
// Below 0.5 the mixed resample crosses only at k = 3: 0.2 s w.p. ¼, 0.6 s w.p. ¾.
TEST(FirstCrossing, TheBootstrapIntervalSpansTheTrialsOwnTimes) {
  ConfigStatistics s = withTrials({}, {{1, 0, 0, 0, 0}, {1, 1, 1, 0, 0}});
  const CrossingTime onset = firstCrossing(s, 0, 0.9, 7);
  EXPECT_DOUBLE_EQ(*onset.time_s, 0.2);  // the mean 0.5 < 0.9 at k = 1
  EXPECT_DOUBLE_EQ(onset.ci.low, 0.2);
  EXPECT_DOUBLE_EQ(onset.ci.high, 0.6);  // the resample {late, late}, probability 1/4
  const CrossingTime half = firstCrossing(s, 0, 0.5, 7);
  EXPECT_DOUBLE_EQ(*half.time_s, 0.6);  // the mean is 0.5 at k = 1, 2: not below 0.5
  EXPECT_DOUBLE_EQ(half.ci.low, 0.2);
  EXPECT_DOUBLE_EQ(half.ci.high, 0.6);
  // The same seed, the same interval; one trial has none.
  EXPECT_EQ(firstCrossing(s, 0, 0.9, 7).ci.high, onset.ci.high);
  EXPECT_FALSE(firstCrossing(withTrials({}, {{1, 0}}), 0, 0.9, 7).ci.bounded());
  // Never below the level: no time, and +∞ at the top of the interval.
  const CrossingTime never = firstCrossing(withTrials({}, {{1, 1}, {1, 1}}), 0, 0.9, 7);
  EXPECT_FALSE(never.time_s);
  EXPECT_TRUE(std::isinf(never.ci.high));
}

TEST(Findings, CatchUpNeedsThreeQuartersOfTheGapClosed) {
  // none 1.0, a-priori 0.6: the gap is 0.4; the dynamic map must be at most 0.6 + 0.1.
  EXPECT_TRUE((CatchUpFinding{"", {0.6, {}}, {0.7, {}}, {1.0, {}}}.holds()));
  EXPECT_FALSE((CatchUpFinding{"", {0.6, {}}, {0.71, {}}, {1.0, {}}}.holds()));
  EXPECT_FALSE((CatchUpFinding{"", {1.0, {}}, {1.0, {}}, {1.0, {}}}.holds()));  // no gap
}

TEST(Findings, FirstOcclusionRankingNeedsStrictOrderAndClearsOnlyOutsideTheIntervals) {
  // Seed 1 of the calibrated layout (report.md): 0.77 [0.65, 0.88], 0.97 [0.94, 1.01], 1.00.
  const FirstOcclusionRanking seen{
      "", {0.77, {0.65, 0.88}}, {0.97, {0.94, 1.01}}, {1.0, {1.0, 1.0}}};
  EXPECT_TRUE(seen.holds());
  EXPECT_FALSE(seen.clear());  // 1.01 is above the no-map value 1.00
  EXPECT_TRUE(
      (FirstOcclusionRanking{"", {0.5, {0.4, 0.6}}, {0.8, {0.7, 0.9}}, {1.0, {1.0, 1.0}}}.clear()));
  EXPECT_FALSE((FirstOcclusionRanking{"", {0.8, {}}, {0.8, {}}, {1.0, {}}}.holds()));  // a tie
  EXPECT_FALSE((FirstOcclusionRanking{"", {0.9, {}}, {0.8, {}}, {1.0, {}}}.holds()));
}

TEST(Findings, NoExperimentsGiveNoFindings) {
  const Findings f = computeFindings({});
  EXPECT_TRUE(f.horizon.empty());
  EXPECT_TRUE(f.wasted.empty());
  EXPECT_TRUE(f.catch_up.empty());
  EXPECT_TRUE(f.first_ranking.empty());
  EXPECT_TRUE(f.reaction.empty());
  EXPECT_FALSE(f.symptoms.single_swarm_never || f.symptoms.reaction_late ||
               f.symptoms.first_occlusion_unranked);
}

}  // namespace
}  // namespace canopy::analysis
