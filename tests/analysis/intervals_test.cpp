#include "analysis/intervals.h"

#include <gtest/gtest.h>

#include <cmath>

namespace canopy::analysis {
namespace {

// Expected Wilson bounds computed by hand from the closed form with z = 1.959963984540054
// (python3: centre = (p + z²/2n)/(1 + z²/n), half = z/(1 + z²/n)·sqrt(p(1−p)/n + z²/4n²)).
TEST(WilsonInterval, MatchesTheClosedFormAtTheEndsAndTheMiddle) {
  const ConfidenceInterval none = wilsonInterval(0, 40);
  EXPECT_EQ(none.low, 0.0);  // exactly 0, not −7e−18
  EXPECT_NEAR(none.high, 0.0876216, 1e-6);
  const ConfidenceInterval half = wilsonInterval(20, 40);
  EXPECT_NEAR(half.low, 0.3519953, 1e-6);
  EXPECT_NEAR(half.high, 0.6480047, 1e-6);
  const ConfidenceInterval all = wilsonInterval(40, 40);
  EXPECT_NEAR(all.low, 0.9123784, 1e-6);
  EXPECT_EQ(all.high, 1.0);  // exactly 1, not 1 + 2e−16
}

TEST(WilsonInterval, IsAsymmetricAwayFromOneHalf) {
  // 29/40 = 72.5 %: [57.17, 83.89] %, the example of issue 10.
  const ConfidenceInterval ci = wilsonInterval(29, 40);
  EXPECT_NEAR(ci.low, 0.5716504, 1e-6);
  EXPECT_NEAR(ci.high, 0.8389198, 1e-6);
  EXPECT_GT(0.725 - ci.low, ci.high - 0.725);  // the longer arm points towards 1/2
  const ConfidenceInterval small = wilsonInterval(3, 10);
  EXPECT_NEAR(small.low, 0.1077913, 1e-6);
  EXPECT_NEAR(small.high, 0.6032219, 1e-6);
}

TEST(WilsonInterval, NoTrialsIsTheWholeUnitInterval) {
  const ConfidenceInterval ci = wilsonInterval(0, 0);
  EXPECT_EQ(ci.low, 0.0);
  EXPECT_EQ(ci.high, 1.0);
}

// Expected quantiles from printed t tables, checked by a second method (Simpson integration of
// the t density and bisection in python3): 12.7062, 4.3027, 3.1824, 2.2622, 2.0227, 1.9799.
TEST(StudentTQuantile, MatchesTabulatedQuantiles) {
  EXPECT_NEAR(studentTQuantile(0.975, 1), 12.7062047, 1e-6);  // tan(0.475 π)
  EXPECT_NEAR(studentTQuantile(0.975, 2), 4.3026527, 1e-6);
  EXPECT_NEAR(studentTQuantile(0.975, 3), 3.1824463, 1e-6);
  EXPECT_NEAR(studentTQuantile(0.975, 9), 2.2621572, 1e-6);
  EXPECT_NEAR(studentTQuantile(0.975, 39), 2.0226909, 1e-6);
  EXPECT_NEAR(studentTQuantile(0.975, 120), 1.9799304, 1e-6);
  EXPECT_NEAR(studentTQuantile(0.95, 9), 1.8331129, 1e-6);
  EXPECT_EQ(studentTQuantile(0.5, 7), 0.0);
}

TEST(StudentTQuantile, ApproachesTheNormalQuantileAsTheExpansionSays) {
  // Cornish–Fisher (Abramowitz & Stegun 26.7.5): t ≈ z + (z³ + z)/4ν + (5z⁵ + 16z³ + 3z)/96ν²,
  // 1.9600826052 for ν = 20000 (python3).
  EXPECT_NEAR(studentTQuantile(0.975, 20000), 1.9600826052, 1e-8);
}

TEST(SampleMoments, MeanAndUnbiasedVarianceOfASmallSample) {
  SampleMoments sample;
  for (const double x : {1.0, 2.0, 3.0, 4.0, 5.0}) sample.add(x);
  EXPECT_EQ(sample.count(), 5);
  EXPECT_DOUBLE_EQ(sample.mean(), 3.0);
  EXPECT_DOUBLE_EQ(sample.variance(), 2.5);  // Σ(x − 3)² / 4 = 10 / 4
}

TEST(MeanInterval, StudentTIntervalOfASmallSample) {
  // 3 ± t_{0.975,4} · √(2.5/5) = 3 ± 2.7764451 · 0.7071068 (t from Simpson integration in python3).
  const ConfidenceInterval ci = meanInterval(std::vector<double>{1, 2, 3, 4, 5});
  EXPECT_NEAR(ci.low, 1.0367568, 1e-6);
  EXPECT_NEAR(ci.high, 4.9632432, 1e-6);
}

TEST(MeanInterval, ConstantSampleIsAPointFromFiveTrialsAndNoIntervalFromFewer) {
  const ConfidenceInterval constant = meanInterval(std::vector<double>{2, 2, 2, 2, 2});
  EXPECT_EQ(constant.low, 2.0);
  EXPECT_EQ(constant.high, 2.0);
  // Two or four agreeing trials: too few to claim a spread of nil.
  EXPECT_FALSE(meanInterval(std::vector<double>{2, 2}).bounded());
  EXPECT_FALSE(meanInterval(std::vector<double>{2, 2, 2, 2}).bounded());
  const ConfidenceInterval single = meanInterval(std::vector<double>{2});
  EXPECT_FALSE(single.bounded());
  EXPECT_TRUE(single.contains(1e9));
}

// {0.5, 0.75, 1, 1}: x̄ = 0.8125, s² = 0.171875 / 3 = 0.0572917, t_{0.975,3} = 3.1824463. The
// plain t interval is 0.8125 ± 0.3808700 = [0.43163, 1.19337], past 1. On the logit scale
// (python3, the closed form of intervals.h): η = ln(0.8125/0.1875) = 1.4663371,
// se_η = 0.2393568 / (2 · 0.8125 · 0.1875) = 0.7855812, η ± t·se_η → σ(·) = [0.2623610, 0.9814107].
TEST(BoundedMeanInterval, StaysInsideTheRangeByTheLogitClosedForm) {
  SampleMoments sample;
  for (const double x : {0.5, 0.75, 1.0, 1.0}) sample.add(x);
  EXPECT_GT(meanInterval(sample).high, 1.0);  // what the report printed before
  const ConfidenceInterval ci = boundedMeanInterval(sample, 0.0, 1.0);
  EXPECT_NEAR(ci.low, 0.2623610, 1e-6);
  EXPECT_NEAR(ci.high, 0.9814107, 1e-6);
  // The same values as footprints of two UAVs, in [0, 2]: the interval scales with the range.
  SampleMoments doubled;
  for (const double x : {1.0, 1.5, 2.0, 2.0}) doubled.add(x);
  const ConfidenceInterval two = boundedMeanInterval(doubled, 0.0, 2.0);
  EXPECT_NEAR(two.low, 2 * 0.2623610, 2e-6);
  EXPECT_NEAR(two.high, 2 * 0.9814107, 2e-6);
}

TEST(BoundedMeanInterval, AtABoundIsThatPointAndTooFewAgreeingTrialsHaveNone) {
  const Estimate all_one = boundedMeanOf({1, 1, 1, 1, 1}, 0.0, 1.0);
  EXPECT_EQ(all_one.ci.low, 1.0);
  EXPECT_EQ(all_one.ci.high, 1.0);
  EXPECT_EQ(all_one.trials, 5);
  EXPECT_FALSE(boundedMeanOf({0.75, 0.75}, 0.0, 1.0).ci.bounded());  // issue 28's [75.0, 75.0]
  EXPECT_FALSE(boundedMeanOf({1, 1, 1}, 0.0, 1.0).ci.bounded());
  EXPECT_FALSE(boundedMeanOf({0.3}, 0.0, 1.0).ci.bounded());
}

TEST(CsvNumber, AnUnboundedEndIsAnEmptyFieldNotInf) {
  // One trial: no interval, ends ±inf; in a CSV they are empty fields (issue 51: pandas read
  // "-inf,inf" as numbers and drew bands of infinite height).
  const Estimate one = meanOf({2.5});
  EXPECT_FALSE(one.ci.bounded());
  EXPECT_EQ(csvNumber(one.value), "2.5");
  EXPECT_EQ(csvNumber(one.ci.low), "");
  EXPECT_EQ(csvNumber(one.ci.high), "");
  EXPECT_EQ(csvNumber(one.ci.width()), "");
  EXPECT_EQ(csvNumber(std::nan("")), "");
  EXPECT_EQ(csvNumber(0.0876216), "0.0876216");
}

}  // namespace
}  // namespace canopy::analysis
