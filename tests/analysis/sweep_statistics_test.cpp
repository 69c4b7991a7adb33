// Per-configuration statistics from hand-made trials: every count, fraction and interval below
// is derived by hand from the visibility and footprint tables written in the tests.
#include "analysis/sweep_statistics.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "analysis/sweep_analysis.h"
#include "core/text_file.h"

namespace canopy::analysis {
namespace {

constexpr experiments::TargetBits I = 1, II = 2;

// Two UAVs, two targets, m = 1 (ownership = visibility): M0 = ({I}, {II}), M* = ({II}, {I}).
spec::ScenarioSpec twoByTwo() {
  spec::ScenarioSpec spec;
  spec.dt = 0.2;
  spec.uavs.resize(2);
  spec.uavs[0].name = "UAV1";
  spec.uavs[1].name = "UAV2";
  spec.targets.resize(2);
  spec.targets[0].name = "I";
  spec.targets[1].name = "II";
  spec.analysis.m = 1;
  spec.analysis.states = {{"M0", {{0}, {1}}, false}, {"M*", {{1}, {0}}, false}};
  return spec;
}

// A trial of five steps (K = 4, Sankey columns at k = 0..4): visible[k] per UAV, the number of
// footprints on I per step (UAV1's footprint first), and a constant OSPA.
experiments::TrialResult trial(const std::vector<std::vector<experiments::TargetBits>>& visible,
                               const std::vector<int>& footprints_on_I, double ospa) {
  experiments::TrialResult t;
  t.dt = 0.2;
  t.uavs = 2;
  t.targets = 2;
  t.visible = visible;
  for (const int n : footprints_on_I) t.in_footprint.push_back({n >= 1 ? I : 0, n >= 2 ? I : 0});
  t.occluded.assign(visible.size(), 0);
  t.ospa.assign(visible.size(), ospa);
  t.trace.assign(visible.size(), 2.0 * ospa);
  return t;
}

const std::vector<experiments::TargetBits> kM0{I, II}, kMStar{II, I}, kMiss1{I, 0};

// A: M0, Miss 1, M*, M*, M0 — in M* at L/2 and reached it by then, back to M0 at L.
// B: M0 throughout.
// C: M0, M0, M0, M*, M* — reaches M* only after L/2.
std::vector<experiments::TrialResult> threeTrials() {
  return {trial({kM0, kMiss1, kMStar, kMStar, kM0}, {1, 1, 1, 1, 1}, 1.0),
          trial({kM0, kM0, kM0, kM0, kM0}, {2, 2, 2, 2, 2}, 2.0),
          trial({kM0, kM0, kM0, kMStar, kMStar}, {0, 0, 1, 2, 0}, 3.0)};
}

TEST(TrialBehaviour, FirstStepInEachNamedStateUsesTheSankeyClassifier) {
  const TrialBehaviour b = analyseTrial(threeTrials()[0], twoByTwo());
  EXPECT_EQ(b.states[1], "Miss 1");
  ASSERT_EQ(b.first_step_in.size(), 2u);
  EXPECT_EQ(b.first_step_in[0], 0);                                            // M0 at k = 0
  EXPECT_EQ(b.first_step_in[1], 2);                                            // M* first at k = 2
  EXPECT_EQ(analyseTrial(threeTrials()[1], twoByTwo()).first_step_in[1], -1);  // never in M*
}

TEST(ConfigStatistics, InStateAtAColumnAndReachedByItDiffer) {
  const ConfigStatistics s = summarise(threeTrials(), twoByTwo(), "c", {});
  ASSERT_EQ(s.columns[2], 2);
  // At L/2 (k = 2) only A is in M*; by k = 2 only A has been in M*; by L (k = 4) A and C have.
  EXPECT_EQ(s.reachedBy("M*", 2), 1);
  EXPECT_EQ(s.reachedBy("M*", 4), 2);
  EXPECT_EQ(s.reachedBy("M0", 0), 3);
  EXPECT_EQ(s.reachedBy("Other", 4), 0);  // not a named state
  // At L: A and B in M0, C in M*. Wilson 1/3 = [0.0614919, 0.7923404], 2/3 = [0.2076596,
  // 0.9385081] (python3, closed form).
  const Estimate m_star = s.stateEstimate("M*", 4);
  EXPECT_DOUBLE_EQ(m_star.value, 1.0 / 3.0);
  EXPECT_NEAR(m_star.ci.low, 0.0614919, 1e-6);
  EXPECT_NEAR(m_star.ci.high, 0.7923404, 1e-6);
  const Estimate m0 = s.stateEstimate("M0", 4);
  EXPECT_NEAR(m0.ci.low, 0.2076596, 1e-6);
  EXPECT_NEAR(m0.ci.high, 0.9385081, 1e-6);
  const std::array<int, 5> a{0, 2, 1, 1, 0};  // indices into M0, M*, Miss 1, Miss >1, Other
  EXPECT_EQ(s.trial_states[0], a);
}

TEST(ConfigStatistics, PerTrialCoverageOverAnIntervalAndItsTInterval) {
  const ConfigStatistics s = summarise(threeTrials(), twoByTwo(), "c", {});
  // Steps 1..3 on I: A 1, 1, 1 → 1; B 2, 2, 2 → 2; C 0, 1, 2 → 1.
  const std::vector<double> expected{1.0, 2.0, 1.0};
  EXPECT_EQ(s.trialCoverageOver(0, {1, 3}), expected);
  // Mean 4/3, s² = 1/3: the plain t interval 4/3 ± t_{0.975,2}/3 (t_{0.975,2} = 4.3026527) is
  // [−0.1008842, 2.7675509], past the two UAVs' [0, 2]. On the logit scale of x/2 (python3, the
  // closed form of intervals.h): u = 2/3, η = ln 2, se_η = (√(1/3)/2) / (√3 · 2/9) = 0.75,
  // 2 · σ(ln 2 ∓ 4.3026527 · 0.75) = [0.1470390, 1.9610950].
  const Estimate e = s.coverageOver(0, {1, 3});
  EXPECT_DOUBLE_EQ(e.value, 4.0 / 3.0);
  EXPECT_NEAR(e.ci.low, 0.1470390, 1e-6);
  EXPECT_NEAR(e.ci.high, 1.9610950, 1e-6);
  EXPECT_EQ(e.trials, 3);
}

TEST(ConfigStatistics, PerStepMeansCarryTIntervals) {
  const ConfigStatistics s = summarise(threeTrials(), twoByTwo(), "c", {});
  // Step 4 on I: 1, 2, 0 → mean 1, s² = 1; on the logit scale of x/2: u = 1/2, η = 0,
  // se_η = (1/2) / (√3 · 1/4) = 1.1547005, 2 · σ(∓ 4.3026527 · 1.1547005) = [0.0138142, 1.9861858]
  // (python3), where the plain t interval 1 ± 2.4841377 leaves [0, 2].
  EXPECT_DOUBLE_EQ(s.coverage[0][4], 1.0);
  EXPECT_NEAR(s.coverage_ci[0][4].low, 0.0138142, 1e-6);
  EXPECT_NEAR(s.coverage_ci[0][4].high, 1.9861858, 1e-6);
  // Step 2 on I: 1, 2, 1 → as coverageOver above, [0.1470390, 1.9610950].
  EXPECT_NEAR(s.coverage_ci[0][2].high, 1.9610950, 1e-6);
  // OSPA 1, 2, 3 at every step → 2 ± 2.4841377 = [−0.4841377, 4.4841377], cut at 0; tr(P) twice.
  EXPECT_DOUBLE_EQ(s.ospa[4], 2.0);
  EXPECT_EQ(s.ospa_ci[4].low, 0.0);
  EXPECT_NEAR(s.ospa_ci[4].high, 4.4841377, 1e-6);
  EXPECT_NEAR(s.trace_ci[4].high, 2.0 * 4.4841377, 1e-6);
  EXPECT_TRUE(s.team_ospa.empty());  // trials without the team's figures: none summarised
}

TEST(ConfigStatistics, TeamFiguresPerStepWithIntervals) {
  std::vector<experiments::TrialResult> trials = threeTrials();
  // Team OSPA 1, 2, 3 m and held fractions 0.5, 1, 1 at every step.
  const double held[] = {0.5, 1.0, 1.0};
  for (std::size_t i = 0; i < trials.size(); ++i) {
    trials[i].team_ospa.assign(trials[i].ospa.size(), static_cast<double>(i + 1));
    trials[i].held.assign(trials[i].ospa.size(), held[i]);
  }
  const ConfigStatistics s = summarise(trials, twoByTwo(), "c", {});
  ASSERT_EQ(s.team_ospa.size(), 5u);
  EXPECT_DOUBLE_EQ(s.team_ospa[2], 2.0);  // as OSPA above: 2 ± 2.4841377, cut at 0
  EXPECT_EQ(s.team_ospa_ci[2].low, 0.0);
  EXPECT_NEAR(s.team_ospa_ci[2].high, 4.4841377, 1e-6);
  EXPECT_NEAR(s.held[2], 2.5 / 3.0, 1e-12);
  EXPECT_LE(s.held_ci[2].high, 1.0);  // a fraction's interval stays in [0, 1]
  EXPECT_LT(s.held_ci[2].low, s.held[2]);
  trials[1].team_ospa.clear();  // one trial file from before: no team figures at all
  trials[1].held.clear();
  EXPECT_TRUE(summarise(trials, twoByTwo(), "c", {}).team_ospa.empty());
}

TEST(WriteTables, OwnershipStatesCarryWilsonBoundsAndReachedCounts) {
  SweepAnalysis analysis;
  analysis.name = "hand";
  analysis.specs = {twoByTwo()};
  analysis.configs = {summarise(threeTrials(), twoByTwo(), "c", {})};
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "canopy_sweep_statistics_test";
  std::filesystem::remove_all(dir);
  writeTables(analysis, dir);
  const std::string csv = readTextFile(dir / "ownership_states.csv").value();
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "config,column,step,t_s,state,trials,fraction,fraction_low,fraction_high,"
            "reached_trials,reached_fraction,reached_low,reached_high");
  // Column 2, M*: 1 of 3 in it and 1 of 3 reached it (Wilson 1/3 as above).
  EXPECT_NE(csv.find("\"c\",2,2,0.4,\"M*\",1,0.333333,0.0614919,0.79234,1,0.333333,0.0614919,"
                     "0.79234\n"),
            std::string::npos)
      << csv;
  // Column 4, M*: 1 of 3 in it, 2 of 3 reached it; "Other" has no reached columns.
  EXPECT_NE(csv.find("\"c\",4,4,0.8,\"M*\",1,0.333333,0.0614919,0.79234,2,0.666667,0.20766,"
                     "0.938508\n"),
            std::string::npos);
  EXPECT_NE(csv.find("\"c\",4,4,0.8,\"Other\",0,0,0,0.561497,,,,\n"), std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST(WriteTables, TrackingCarriesTheTeamFiguresWhenTheTrialsHaveThem) {
  std::vector<experiments::TrialResult> trials = threeTrials();
  for (std::size_t i = 0; i < trials.size(); ++i) {  // team OSPA 1, 2, 3 m; held 1 everywhere
    trials[i].team_ospa.assign(trials[i].ospa.size(), static_cast<double>(i + 1));
    trials[i].held.assign(trials[i].ospa.size(), 1.0);
  }
  SweepAnalysis analysis;
  analysis.name = "hand";
  analysis.specs = {twoByTwo(), twoByTwo()};
  analysis.configs = {summarise(trials, twoByTwo(), "team", {}),
                      summarise(threeTrials(), twoByTwo(), "old", {})};
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "canopy_sweep_tracking_test";
  std::filesystem::remove_all(dir);
  writeTables(analysis, dir);
  const std::string csv = readTextFile(dir / "tracking.csv").value();
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "config,step,t_s,mean_ospa_m,mean_ospa_low_m,mean_ospa_high_m,mean_trace_pos_m2,"
            "mean_trace_pos_low_m2,mean_trace_pos_high_m2,mean_team_ospa_m,mean_team_ospa_low_m,"
            "mean_team_ospa_high_m,mean_held,mean_held_low,mean_held_high");
  // Step 2: OSPA and team OSPA 2 ± 2.4841377 (cut at 0), tr 4 ± 4.9682754 (cut at 0); held 1 in
  // all three trials: no spread from three trials is too few to bound (intervals.h's rule), and
  // an unbounded interval's ends are empty fields, never ±inf (issue 51).
  EXPECT_NE(csv.find("\"team\",2,0.4,2,0,4.48414,4,0,8.96828,2,0,4.48414,1,,\n"),
            std::string::npos)
      << csv;
  EXPECT_NE(csv.find("\"old\",2,0.4,2,0,4.48414,4,0,8.96828,,,,,,\n"), std::string::npos) << csv;
  EXPECT_EQ(csv.find("inf"), std::string::npos) << csv;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace canopy::analysis
