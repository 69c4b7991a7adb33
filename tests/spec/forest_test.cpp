#include "spec/forest.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace canopy::spec {
namespace {

double minimumGap(const std::vector<world::TreeDef>& trees) {
  double gap = INFINITY;  // O(n²): fine for test sizes, and independent of the code under test
  for (std::size_t a = 0; a < trees.size(); ++a) {
    for (std::size_t b = a + 1; b < trees.size(); ++b) {
      gap = std::min(
          gap, (trees[a].centre - trees[b].centre).norm() - trees[a].radius - trees[b].radius);
    }
  }
  return gap;
}

TEST(PoissonForest, CountIsPoissonWithMeanLambdaTimesArea) {
  // N ~ Poisson(λA): over 30 seeds, the mean count lies within 4 standard errors of λA.
  const Aabb region{Vec2(0, 0), Vec2(400, 250)};
  const double lambda = 0.01, expected = lambda * region.area();  // 1000 trees
  double sum = 0.0, sum2 = 0.0;
  const int seeds = 30;
  for (int s = 0; s < seeds; ++s) {
    const auto trees = poissonForest(
        {region, lambda, {1.0, 2.0}, static_cast<std::uint64_t>(s), std::nullopt, SIZE_MAX});
    for (const auto& tree : trees) {
      ASSERT_TRUE(region.contains(tree.centre));
      ASSERT_GE(tree.radius, 1.0);
      ASSERT_LE(tree.radius, 2.0);
    }
    sum += static_cast<double>(trees.size());
    sum2 += static_cast<double>(trees.size() * trees.size());
  }
  const double mean = sum / seeds, var = sum2 / seeds - mean * mean;
  EXPECT_NEAR(mean, expected, 4.0 * std::sqrt(expected / seeds));
  EXPECT_NEAR(var / expected, 1.0, 0.6);  // Poisson: variance = mean (loose: 30 samples)
}

TEST(PoissonForest, PointsAreSpatiallyUniform) {
  const Aabb region{Vec2(0, 0), Vec2(100, 100)};
  const auto trees = poissonForest({region, 0.5, {0.1, 0.1}, 3, std::nullopt, SIZE_MAX});  // ~5000
  int left = 0, bottom = 0;
  for (const auto& tree : trees) {
    left += tree.centre.x() < 50.0;
    bottom += tree.centre.y() < 50.0;
  }
  const double n = static_cast<double>(trees.size());
  EXPECT_NEAR(left / n, 0.5, 4 * 0.5 / std::sqrt(n));
  EXPECT_NEAR(bottom / n, 0.5, 4 * 0.5 / std::sqrt(n));
}

TEST(PoissonForest, MinimumGapIsRespectedAndDensityMatchesMaternII) {
  const Aabb region{Vec2(0, 0), Vec2(300, 300)};
  const double lambda = 0.02, r = 1.5, gap = 2.0;
  // Matérn II intensity by hand: D = 2r + gap = 5, λπD² = 1.5708, (1 − e^−1.5708)/(π·25) =
  // 0.010221.
  const double expected_intensity =
      (1.0 - std::exp(-lambda * std::numbers::pi * 25.0)) / (std::numbers::pi * 25.0);
  EXPECT_NEAR(maternIIIntensity(lambda, r, gap), expected_intensity, 1e-15);
  double total = 0.0;
  const int seeds = 10;
  for (int s = 0; s < seeds; ++s) {
    const auto trees =
        poissonForest({region, lambda, {r, r}, static_cast<std::uint64_t>(100 + s), gap});
    EXPECT_GE(minimumGap(trees), gap - 1e-9);
    total += static_cast<double>(trees.size());
  }
  const double expected = expected_intensity * region.area() * seeds;  // ≈ 9200
  // A hard-core count is less dispersed than a Poisson one; the Poisson bound is conservative.
  EXPECT_NEAR(total, expected, 4.0 * std::sqrt(expected));
}

TEST(PoissonForest, SameSeedSameForestOtherSeedOtherForest) {
  const PoissonForestDef def{{Vec2(0, 0), Vec2(50, 50)}, 0.05, {0.5, 1.0}, 9, 0.5};
  const auto a = poissonForest(def), b = poissonForest(def);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].centre, b[k].centre);
    EXPECT_EQ(a[k].radius, b[k].radius);
  }
  PoissonForestDef other = def;
  other.seed = 10;
  EXPECT_NE(poissonForest(other).front().centre, a.front().centre);
}

TEST(GridForest, PlacesRowsAndColumnsOnTheRotatedLattice) {
  GridForestDef def;
  def.origin = Vec2(10, 20);
  def.spacing = Vec2(4, 6);
  def.rows = 2;
  def.cols = 3;
  def.angle = std::numbers::pi / 2;  // columns go north, rows go west
  def.radius = {1.0, 1.0};
  const auto trees = gridForest(def);
  ASSERT_EQ(trees.size(), 6u);
  // Tree (row 1, col 2): origin + Rot(90°)(2·4, 1·6) = (10 − 6, 20 + 8).
  EXPECT_NEAR(trees[5].centre.x(), 4.0, 1e-12);
  EXPECT_NEAR(trees[5].centre.y(), 28.0, 1e-12);
  EXPECT_DOUBLE_EQ(trees[5].radius, 1.0);
}

TEST(ClusterForest, MeanCountIsParentIntensityTimesClusterSizeTimesArea) {
  const Aabb region{Vec2(0, 0), Vec2(500, 500)};
  ClusterForestDef def;
  def.region = region;
  def.parent_lambda = 2e-4;  // 50 clusters expected
  def.mean_trees = 8.0;
  def.spread = 6.0;
  def.radius = {1.0, 1.0};
  double total = 0.0;
  const int seeds = 20;
  for (int s = 0; s < seeds; ++s) {
    def.seed = static_cast<std::uint64_t>(s);
    total += static_cast<double>(clusterForest(def).size());
  }
  const double expected = 2e-4 * 8.0 * region.area();  // 400 per forest
  // Var(N) of a Poisson cluster process ≈ λ_p A (μ + μ²) = 50 · 72 = 3600 per forest.
  EXPECT_NEAR(total / seeds, expected, 4.0 * std::sqrt(3600.0 / seeds));
  def.min_gap = 0.5;
  EXPECT_GE(minimumGap(clusterForest(def)), 0.5 - 1e-9);
}

}  // namespace
}  // namespace canopy::spec
