#include "analysis/report_numbers.h"

#include <gtest/gtest.h>

#include <limits>

namespace canopy::analysis {
namespace {

TEST(ReportNumbers, ProportionInPercentWithItsWilsonInterval) {
  // 29/40: Wilson [0.571650, 0.838920] (python3, closed form).
  EXPECT_EQ(percentWithInterval(proportion(29, 40)), "72.5 % [57.2, 83.9]");
  EXPECT_EQ(percentWithInterval(proportion(0, 40)), "0.0 % [0.0, 8.8]");
  EXPECT_EQ(percentWithInterval(meanOf({0.25})), "25.0 % [too few trials: 1]");
  EXPECT_EQ(percentWithInterval(boundedMeanOf({0.75, 0.75}, 0, 1)), "75.0 % [too few trials: 2]");
}

TEST(ReportNumbers, MeanWithItsIntervalOrNoneForOneTrial) {
  EXPECT_EQ(numberWithInterval({0.99, {0.951, 1.034}}), "0.99 [0.95, 1.03]");
  EXPECT_EQ(numberWithInterval(meanOf({2.0})), "2.00 [too few trials: 1]");
  EXPECT_EQ(numberWithInterval({3.26, {3.0, 3.5}}, "%.1f s"), "3.3 s [3.0 s, 3.5 s]");
}

TEST(ReportNumbers, PaperVerdictSaysInsideAndHowFar) {
  // 29/40 = 72.5 % [57.2, 83.9]: the paper's 85 % is outside but 12.5 pts away; 97.5 % is 25 pts.
  const Estimate ours = proportion(29, 40);
  EXPECT_EQ(paperVerdict(0.85, ours), "no; Δ +12.5 pts (within ±15)");
  EXPECT_EQ(paperVerdict(0.975, ours), "no; Δ +25.0 pts (beyond ±15)");
  EXPECT_EQ(paperVerdict(0.70, ours), "yes; Δ −2.5 pts");
  // 40/40 = [91.2, 100]: 100 % is inside, at Δ 0.
  EXPECT_EQ(paperVerdict(1.0, proportion(40, 40)), "yes; Δ ±0.0 pts");
  // 0/40 against 12.5 %: outside [0, 8.8], 12.5 pts off.
  EXPECT_EQ(paperVerdict(0.125, proportion(0, 40)), "no; Δ +12.5 pts (within ±15)");
}

TEST(ReportNumbers, CrossingTimesWithTheirIntervalAndTheVerdictInSeconds) {
  const double inf = std::numeric_limits<double>::infinity();
  const CrossingTime onset{1.8, {1.6, 2.0}};
  EXPECT_EQ(timeWithInterval(onset), "1.8 s [1.6, 2.0]");
  EXPECT_EQ(timeVerdict(1.6, onset), "yes; Δ −0.2 s");
  EXPECT_EQ(timeVerdict(2.2, onset), "no; Δ +0.4 s");
  EXPECT_EQ(timeWithInterval({3.0, {2.6, inf}}), "3.0 s [2.6, never]");
  EXPECT_EQ(timeWithInterval({std::nullopt, {inf, inf}}), "never");
  EXPECT_EQ(timeVerdict(1.6, {std::nullopt, {inf, inf}}), "no (never crosses)");
  EXPECT_EQ(timeWithInterval({0.4, {-inf, inf}}), "0.4 s [too few trials]");
}

// A case with the verdict it should be given, to count.
struct Case {
  Verdict v;
  Verdict verdict() const { return v; }
};

TEST(ReportNumbers, AFindingHoldsOnlyWhenEveryCaseHoldsElseEachVerdictIsCounted) {
  EXPECT_EQ(verdictOf(std::vector<Case>{{Verdict::holds}, {Verdict::holds}}), "holds");
  EXPECT_EQ(verdictOf(std::vector<Case>{
                {Verdict::holds}, {Verdict::consistent}, {Verdict::consistent}, {Verdict::fails}}),
            "holds in 1, consistent in 2, fails in 1 of 4 cases");
  EXPECT_EQ(verdictOf(std::vector<Case>{{Verdict::consistent}, {Verdict::too_few_trials}}),
            "consistent in 1, too few trials in 1 of 2 cases");
}

}  // namespace
}  // namespace canopy::analysis
