// The report's findings computed as values, on hand-built statistics whose answers are worked
// out by hand in the comments.
#include "analysis/findings.h"

#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <filesystem>
#include <limits>
#include <string_view>

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
  // Two trials each, not all alike: logit-t intervals, and with two trials they overlap.
  EXPECT_EQ(f.horizon[0].verdict(), Verdict::consistent);
}

// The rule of report.md, case by case: a claim "above > below" from two intervals.
TEST(Verdicts, HoldWhenTheIntervalsSeparateAsClaimedFailTheOtherWayElseConsistent) {
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(claimAbove({0.5, 0.7}, {0.2, 0.4}), Verdict::holds);
  EXPECT_EQ(claimAbove({0.3, 0.6}, {0.2, 0.4}), Verdict::consistent);
  EXPECT_EQ(claimAbove({0.4, 0.6}, {0.2, 0.4}), Verdict::consistent);  // touching: not apart
  EXPECT_EQ(claimAbove({0.1, 0.15}, {0.2, 0.4}), Verdict::fails);
  EXPECT_EQ(claimAbove({-inf, inf}, {0.2, 0.4}), Verdict::too_few_trials);
  EXPECT_EQ(claimAbove({0.5, inf}, {0.2, 0.4}), Verdict::holds);  // "never" as the upper end
  // Issue 28's case: 0.73 [0.00, 2.00] with the map vs 1.20 [1.00, 1.40] without: no verdict
  // either way from these trials.
  EXPECT_EQ((WastedCoverageCase{"", "", "", "", {0.73, {0.0, 2.0}}, {1.2, {1.0, 1.4}}}.verdict()),
            Verdict::consistent);
  EXPECT_EQ(allOf({Verdict::holds, Verdict::holds}), Verdict::holds);
  EXPECT_EQ(allOf({Verdict::holds, Verdict::consistent}), Verdict::consistent);
  EXPECT_EQ(allOf({Verdict::consistent, Verdict::fails}), Verdict::fails);
  EXPECT_EQ(allOf({Verdict::fails, Verdict::too_few_trials}), Verdict::too_few_trials);
  EXPECT_STREQ(verdictText(Verdict::too_few_trials), "too few trials");
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
  EXPECT_FALSE(f.reaction[0].onset.ci.bounded());  // two alike trials: too few for [2.6, 2.6]
  EXPECT_FALSE(f.reaction[1].onset.time_s);        // the dynamic map never leaves I
  EXPECT_DOUBLE_EQ(*f.reaction[2].onset.time_s, 10 * 0.2);
  // Two alike trials: a zero-width bootstrap interval from fewer than 5 trials is refused.
  EXPECT_EQ(*reactsBeforeHiding(f.reaction, second), Verdict::too_few_trials);
  EXPECT_EQ(*reactsBeforeHiding(f.reaction, step), Verdict::too_few_trials);
  EXPECT_TRUE(f.symptoms.reaction_late);                 // judged at decisions every 1 s
  EXPECT_FALSE(dynamicReactsLater(f.reaction, second));  // the dynamic map never gets half-way
  EXPECT_EQ(*dynamicReactsLater(f.reaction, step), Verdict::too_few_trials);
}

TEST(Findings, ReactionVerdictsFollowTheBootstrapIntervals) {
  // Five alike trials: a zero-width interval is allowed, and the times decide.
  ExperimentResult je = experiment("joint_effect", {"I", "II"});
  const std::vector<int> early = {1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 0, 0, 0, 0};  // from k = 10
  const std::vector<int> late = {1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 0};   // from k = 13
  const std::vector<std::vector<int>> five_early(5, early), five_late(5, late);
  je.analysis.configs = {
      withTrials({"planner.occlusion_map=\"a_priori\"", "planner.replan_period=1.0"}, five_late),
      withTrials({"planner.occlusion_map=\"dynamic\"", "planner.replan_period=1.0"}, five_late),
      withTrials({"planner.occlusion_map=\"a_priori\"", "planner.replan_period=0.2"}, five_early),
      withTrials({"planner.occlusion_map=\"dynamic\"", "planner.replan_period=0.2"}, five_late)};
  const Findings f = computeFindings({je});
  const std::string second = decisionPeriods()[0].label, step = decisionPeriods()[1].label;
  EXPECT_EQ(*reactsBeforeHiding(f.reaction, second), Verdict::fails);       // [2.6, 2.6] after 2.2
  EXPECT_EQ(*reactsBeforeHiding(f.reaction, step), Verdict::holds);         // [2.0, 2.0] before 2.2
  EXPECT_EQ(*dynamicReactsLater(f.reaction, second), Verdict::consistent);  // the same times
  EXPECT_EQ(*dynamicReactsLater(f.reaction, step), Verdict::holds);         // 2.6 after 2.0
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

TEST(Findings, CatchUpNeedsThreeQuartersOfTheGapClosedByTheIntervals) {
  // a-priori 0.6 [0.55, 0.65], none 1.0 [0.95, 1.0]: threshold 0.75·a + 0.25·n has the interval
  // [0.75·0.55 + 0.25·0.95, 0.75·0.65 + 0.25·1.0] = [0.65, 0.7375].
  const Estimate a_priori{0.6, {0.55, 0.65}}, none{1.0, {0.95, 1.0}};
  const CatchUpFinding below{"", a_priori, {0.6, {0.58, 0.64}}, none};
  EXPECT_DOUBLE_EQ(below.threshold().low, 0.65);
  EXPECT_DOUBLE_EQ(below.threshold().high, 0.7375);
  EXPECT_EQ(below.verdict(), Verdict::holds);  // 0.64 < 0.65
  EXPECT_EQ((CatchUpFinding{"", a_priori, {0.7, {0.66, 0.74}}, none}.verdict()),
            Verdict::consistent);
  EXPECT_EQ((CatchUpFinding{"", a_priori, {0.8, {0.75, 0.85}}, none}.verdict()),
            Verdict::fails);  // 0.75 > 0.7375
  // No gap: the no-map interval does not lie above the a-priori one.
  EXPECT_EQ((CatchUpFinding{"", {1.0, {0.9, 1.0}}, {0.5, {0.4, 0.6}}, none}.verdict()),
            Verdict::consistent);
}

TEST(Findings, FirstOcclusionRankingHoldsOnlyWhenEachStepSeparates) {
  // Seed 1 of the calibrated layout (an earlier report.md): 0.77 [0.65, 0.88], 0.97 [0.94, 1.00],
  // 1.00 [1.00, 1.00]: a-priori below dynamic, but dynamic's interval reaches no map's.
  const FirstOcclusionRanking seen{
      "", {0.77, {0.65, 0.88}}, {0.97, {0.94, 1.00}}, {1.0, {1.0, 1.0}}};
  EXPECT_EQ(seen.verdict(), Verdict::consistent);
  EXPECT_EQ((FirstOcclusionRanking{"", {0.5, {0.4, 0.6}}, {0.8, {0.7, 0.9}}, {1.0, {0.95, 1.0}}}
                 .verdict()),
            Verdict::holds);
  EXPECT_EQ((FirstOcclusionRanking{"", {0.9, {0.85, 0.95}}, {0.5, {0.4, 0.6}}, {1.0, {0.95, 1.0}}}
                 .verdict()),
            Verdict::fails);  // dynamic clearly below a-priori
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

namespace canopy::analysis {
namespace {

// The header counts the trials analysed against those run now (issue 28: it said "the others
// resumed from disk" when none were).
TEST(Report, TheHeaderCountsResumedTrialsTruly) {
  ExperimentResult r = experiment("some_study", {"I"});
  r.analysis.specs.front().uavs.emplace_back();  // the configuration section reads one
  ConfigStatistics a = configWith({"x=1"}), b = configWith({"x=2"});
  a.trials = b.trials = 20;
  r.analysis.configs = {a, b};
  ReportContext ctx;
  ctx.trials_run = 40;
  EXPECT_NE(reportMarkdown({r}, ctx).find("; 40 trials, all run now; "), std::string::npos);
  ctx.trials_run = 15;
  EXPECT_NE(reportMarkdown({r}, ctx).find("; 40 trials: 15 run now, 25 resumed from disk; "),
            std::string::npos);
  ctx.trials_run = 0;
  EXPECT_NE(reportMarkdown({r}, ctx).find("; 40 trials, all resumed from disk; "),
            std::string::npos);
  // The verdict rule is stated where the verdicts are.
  EXPECT_NE(reportMarkdown({r}, ctx).find("it **holds** when the intervals separate in the "
                                          "claimed direction"),
            std::string::npos);
}

// Every document report.md cites is in the repository (issue 51: it cited algorithms.md, which
// is not).
TEST(Report, CitesOnlyDocumentsThatExist) {
  ExperimentResult r = experiment("some_study", {"I"});
  r.analysis.specs.front().uavs.emplace_back();
  r.analysis.configs = {configWith({"x=1"})};
  const std::string md = reportMarkdown({r}, ReportContext{});
  // Each ".md" with the path characters before it (no std::regex: GCC 12 warns inside it at -O1).
  int documents = 0;
  for (std::size_t at = md.find(".md"); at != std::string::npos; at = md.find(".md", at + 3)) {
    std::size_t begin = at;
    while (begin > 0 && (std::isalnum(static_cast<unsigned char>(md[begin - 1])) ||
                         std::string_view("_./-").find(md[begin - 1]) != std::string_view::npos))
      --begin;
    const std::string name = md.substr(begin, at + 3 - begin);
    if (name == "report.md") continue;  // the report itself
    ++documents;
    EXPECT_TRUE(std::filesystem::is_regular_file(std::filesystem::path(CANOPY_SOURCE_DIR) / name))
        << "report.md cites " << name << ", which is not in the repository";
  }
  EXPECT_GE(documents, 2);  // docs/design-notes.md and docs/calibration.md at least
}

}  // namespace
}  // namespace canopy::analysis
