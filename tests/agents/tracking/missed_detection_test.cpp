// Negative information after a missed detection, against closed forms of a truncated normal.
#include "agents/tracking/missed_detection.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace canopy::agents::tracking {
namespace {

// E[u^k] of N(0, 1): 1, 0, 1, 0, 3, 0, 15 (k = 0 … 6; (k − 1)!! for even k). The midpoint grid
// over ±4.5σ misses the tails beyond (2·10⁻⁵ of the variance's integrand) and nothing else.
TEST(NormalGrid, approximatesNormalMoments) {
  const NormalGrid& grid = normalGrid();
  const double expected[] = {1.0, 0.0, 1.0, 0.0, 3.0, 0.0, 15.0};
  const double tolerance[] = {1e-12, 1e-12, 2e-4, 1e-12, 4e-3, 1e-12, 0.08};
  for (int k = 0; k <= 6; ++k) {
    double sum = 0.0;
    for (int i = 0; i < NormalGrid::kCells; ++i) sum += grid.weights[i] * std::pow(grid.nodes[i], k);
    EXPECT_NEAR(sum, expected[k], tolerance[k]) << "k = " << k;
  }
}

TargetGaussian standardPrior(double rho) {  // p ~ N(0, I), v = ρ p + ε, Var(v) = 1
  TargetGaussian g;
  g.x.setZero();
  g.P.setIdentity();
  g.P(0, 2) = g.P(2, 0) = rho;
  return g;
}

// A camera that sees the half plane x > 0 with P_D = 1: the posterior is the normal truncated to
// x < 0, whose mean is −√(2/π) and variance 1 − 2/π (half-normal); y is untouched.
TEST(MissedDetection, halfPlaneIsTheTruncatedNormal) {
  const TargetGaussian after =
      afterMissedDetection(standardPrior(0.0), 1.0, [](const Vec2& p) { return p.x() > 0.0; });
  const double mean = -std::sqrt(2.0 / std::numbers::pi), variance = 1.0 - 2.0 / std::numbers::pi;
  EXPECT_NEAR(after.x(0), mean, 0.02 * std::abs(mean));
  EXPECT_NEAR(after.P(0, 0), variance, 0.03 * variance);
  EXPECT_NEAR(after.x(1), 0.0, 1e-12);
  EXPECT_NEAR(after.P(1, 1), 1.0, 1e-3);  // the grid's E[u²] is 1 − 1.3·10⁻⁴
  EXPECT_NEAR(after.P(0, 1), 0.0, 1e-12);
}

// P_D = 0.9: the density is φ·(1 − 0.9·1[x > 0]), a mixture of the two half-normals with masses
// 0.5 and 0.05, so E[x] = (0.5·(−m) + 0.05·m) / 0.55 with m = √(2/π).
TEST(MissedDetection, partialDetectionLeavesSomeMassInView) {
  const TargetGaussian after =
      afterMissedDetection(standardPrior(0.0), 0.9, [](const Vec2& p) { return p.x() > 0.0; });
  const double m = std::sqrt(2.0 / std::numbers::pi);
  const double mean = (0.5 * -m + 0.05 * m) / 0.55;
  const double second = 1.0;  // E[x²] of either half-normal is 1
  EXPECT_NEAR(after.x(0), mean, 0.02 * std::abs(mean));
  EXPECT_NEAR(after.P(0, 0), second - mean * mean, 0.03 * (second - mean * mean));
}

// The velocity follows its regression on the position: v = ρ p + ε with Var(ε) = 1 − ρ², so
// E[v] = ρ E[p], Var(v) = ρ² Var(p) + 1 − ρ², Cov(p, v) = ρ Var(p).
TEST(MissedDetection, velocityFollowsItsRegressionOnPosition) {
  const double rho = 0.6;
  const TargetGaussian after =
      afterMissedDetection(standardPrior(rho), 1.0, [](const Vec2& p) { return p.x() > 0.0; });
  const double var_p = after.P(0, 0);
  EXPECT_NEAR(after.x(2), rho * after.x(0), 1e-12);
  EXPECT_NEAR(after.P(2, 2), rho * rho * var_p + 1.0 - rho * rho, 1e-12);
  EXPECT_NEAR(after.P(0, 2), rho * var_p, 1e-12);
  EXPECT_NEAR(after.P(2, 0), after.P(0, 2), 0.0);
  EXPECT_NEAR(after.x(3), 0.0, 1e-12);
  EXPECT_NEAR(after.P(3, 3), 1.0, 1e-12);
}

// A footprint that sees nothing of the track, or a covariance that is not positive definite:
// the prediction, bit for bit.
TEST(MissedDetection, nothingVisibleKeepsThePrediction) {
  TargetGaussian prior = standardPrior(0.3);
  prior.x << 3.0, -2.0, 0.5, 0.1;
  TargetGaussian after = afterMissedDetection(prior, 0.9, [](const Vec2&) { return false; });
  EXPECT_EQ(after.x, prior.x);
  EXPECT_EQ(after.P, prior.P);
  prior.P(0, 0) = -1.0;
  after = afterMissedDetection(prior, 0.9, [](const Vec2&) { return true; });
  EXPECT_EQ(after.x, prior.x);
  EXPECT_EQ(after.P, prior.P);
}

// A square camera centred on the track and P_D = 1: what is left is symmetric, so the mean stays
// and the spread grows (the second moment of N(0, 1) outside |x|, |y| ≤ 1, by a fine grid: a
// second method; 1.619). The coarse grid counts whole the cells the edge crosses: 11 % high
// (missed_detection.h), so within 15 %.
TEST(MissedDetection, centredSquareKeepsTheMeanAndWidens) {
  auto inside = [](const Vec2& p) { return std::abs(p.x()) <= 1.0 && std::abs(p.y()) <= 1.0; };
  const TargetGaussian after = afterMissedDetection(standardPrior(0.0), 1.0, inside);
  double Z = 0.0, xx = 0.0;
  const double h = 0.01;
  for (double x = -8.0; x < 8.0; x += h) {
    for (double y = -8.0; y < 8.0; y += h) {
      const Vec2 p(x + h / 2, y + h / 2);
      if (inside(p)) continue;
      const double w = std::exp(-0.5 * p.squaredNorm());
      Z += w;
      xx += w * p.x() * p.x();
    }
  }
  EXPECT_NEAR(after.x(0), 0.0, 1e-9);
  EXPECT_NEAR(after.x(1), 0.0, 1e-9);
  EXPECT_NEAR(after.P(0, 0), xx / Z, 0.15 * xx / Z);
  EXPECT_GT(after.P(0, 0), 1.0);
}

}  // namespace
}  // namespace canopy::agents::tracking
