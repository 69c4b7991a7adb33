// The report's findings computed as values, on hand-built statistics whose answers are worked
// out by hand in the comments.
#include "analysis/findings.h"

#include <gtest/gtest.h>

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
  scenarios::ScenarioSpec spec;
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

TEST(Findings, ReactionTimesAreTheFirstStepsBelowTheirThresholds) {
  ExperimentResult je = experiment("joint_effect", {"I", "II"});
  ConfigStatistics a_priori = configWith({"planner.occlusion_map=\"a_priori\""});
  a_priori.coverage = {{1.0, 1.0, 0.95, 0.85, 0.4}, {1, 1, 1, 1, 1}};  // onset k = 3, half k = 4
  ConfigStatistics dynamic = configWith({"planner.occlusion_map=\"dynamic\""});
  dynamic.coverage = {{1.0, 1.0, 1.0, 1.0, 0.7}, {1, 1, 1, 1, 1}};  // onset k = 4, never half
  je.analysis.configs = {a_priori, dynamic};
  const Findings f = computeFindings({je});
  ASSERT_EQ(f.reaction.size(), 2u);
  EXPECT_DOUBLE_EQ(*f.reaction[0].onset_s, 0.6);
  EXPECT_DOUBLE_EQ(*f.reaction[0].half_s, 0.8);
  EXPECT_DOUBLE_EQ(*f.reaction[1].onset_s, 0.8);
  EXPECT_FALSE(f.reaction[1].half_s);
  EXPECT_FALSE(dynamicReactsLater(f.reaction));  // the dynamic map never gets half-way
  EXPECT_FALSE(f.symptoms.reaction_late);         // 0.6 s is before I hides at 2.2 s
  EXPECT_TRUE(*dynamicReactsLater({{"a_priori", 1.0, 3.4}, {"dynamic", 1.0, 3.8}}));
  EXPECT_FALSE(*dynamicReactsLater({{"a_priori", 1.0, 3.8}, {"dynamic", 1.0, 3.4}}));
}

TEST(Findings, CatchUpNeedsThreeQuartersOfTheGapClosed) {
  // none 1.0, a-priori 0.6: the gap is 0.4; the dynamic map must be at most 0.6 + 0.1.
  EXPECT_TRUE((CatchUpFinding{{0.6, {}}, {0.7, {}}, {1.0, {}}}.holds()));
  EXPECT_FALSE((CatchUpFinding{{0.6, {}}, {0.71, {}}, {1.0, {}}}.holds()));
  EXPECT_FALSE((CatchUpFinding{{1.0, {}}, {1.0, {}}, {1.0, {}}}.holds()));  // no gap to close
}

TEST(Findings, FirstOcclusionRankingNeedsStrictOrderAndClearsOnlyOutsideTheIntervals) {
  // Seed 1 of the calibrated layout (report.md): 0.77 [0.65, 0.88], 0.97 [0.94, 1.01], 1.00.
  const FirstOcclusionRanking seen{{0.77, {0.65, 0.88}}, {0.97, {0.94, 1.01}}, {1.0, {1.0, 1.0}}};
  EXPECT_TRUE(seen.holds());
  EXPECT_FALSE(seen.clear());  // 1.01 is above the no-map value 1.00
  EXPECT_TRUE((FirstOcclusionRanking{{0.5, {0.4, 0.6}}, {0.8, {0.7, 0.9}}, {1.0, {1.0, 1.0}}}.clear()));
  EXPECT_FALSE((FirstOcclusionRanking{{0.8, {}}, {0.8, {}}, {1.0, {}}}.holds()));  // a tie
  EXPECT_FALSE((FirstOcclusionRanking{{0.9, {}}, {0.8, {}}, {1.0, {}}}.holds()));
}

TEST(Findings, NoExperimentsGiveNoFindings) {
  const Findings f = computeFindings({});
  EXPECT_TRUE(f.horizon.empty());
  EXPECT_TRUE(f.wasted.empty());
  EXPECT_FALSE(f.catch_up);
  EXPECT_FALSE(f.first_ranking);
  EXPECT_TRUE(f.reaction.empty());
  EXPECT_FALSE(f.symptoms.single_swarm_never || f.symptoms.reaction_late ||
               f.symptoms.first_occlusion_unranked);
}

}  // namespace
}  // namespace canopy::analysis
