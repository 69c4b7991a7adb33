#include "agents/fusion/comm_graph.h"

#include <gtest/gtest.h>

#include <limits>
#include <vector>

namespace canopy::agents::fusion {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

std::vector<RandomStream> streams(int agents, std::uint64_t seed) {
  std::vector<RandomStream> out;
  for (int i = 0; i < agents; ++i) out.emplace_back(seed, "fusion.loss", i);
  return out;
}

TEST(CommGraph, CompleteGraphGivesEqualMetropolisWeights) {
  // deg = N − 1 everywhere: π_ij = 1 / N and π_ii = 1 − (N − 1) / N = 1 / N.
  const std::vector<Vec2> positions = {{0, 0}, {1000, 0}, {0, 5000}, {-3, 7}, {1e6, 1e6}};
  CommGraph graph;
  graph.build(positions, kInf);
  for (int i = 0; i < 5; ++i) {
    ASSERT_EQ(graph.degree(i), 4);
    EXPECT_DOUBLE_EQ(graph.selfWeight(i), 0.2);
    for (const double w : graph.weights(i)) EXPECT_DOUBLE_EQ(w, 0.2);
  }
  EXPECT_EQ(graph.componentCount(), 1);
}

TEST(CommGraph, PathGraphWeightsByHand) {
  // 0 — 1 — 2 — 3 (10 m apart, range 15 m): degrees 1, 2, 2, 1, so every π_ij = 1/3,
  // π_00 = π_33 = 2/3, π_11 = π_22 = 1/3.
  const std::vector<Vec2> positions = {{0, 0}, {10, 0}, {20, 0}, {30, 0}};
  CommGraph graph;
  graph.build(positions, 15.0);
  EXPECT_EQ(std::vector<int>(graph.neighbours(1).begin(), graph.neighbours(1).end()),
            (std::vector<int>{0, 2}));
  EXPECT_TRUE(graph.linked(2, 3));
  EXPECT_FALSE(graph.linked(0, 2));
  EXPECT_NEAR(graph.selfWeight(0), 2.0 / 3.0, 1e-15);
  EXPECT_NEAR(graph.selfWeight(1), 1.0 / 3.0, 1e-15);
  EXPECT_NEAR(graph.selfWeight(3), 2.0 / 3.0, 1e-15);
  for (int i = 0; i < 4; ++i) {
    for (const double w : graph.weights(i)) EXPECT_NEAR(w, 1.0 / 3.0, 1e-15);
  }
}

TEST(CommGraph, AgentsOutOfRangeAreNotLinked) {
  const std::vector<Vec2> positions = {{0, 0}, {40, 0}, {200, 0}, {230, 0}, {1000, 0}};
  CommGraph graph;
  graph.build(positions, 50.0);
  EXPECT_EQ(graph.degree(0), 1);
  EXPECT_FALSE(graph.linked(1, 2));
  EXPECT_EQ(graph.degree(4), 0);
  EXPECT_DOUBLE_EQ(graph.selfWeight(4), 1.0);
  EXPECT_EQ(graph.componentCount(), 3);
  EXPECT_EQ(graph.component(0), graph.component(1));
  EXPECT_EQ(graph.component(2), graph.component(3));
  EXPECT_NE(graph.component(1), graph.component(2));
  EXPECT_EQ(graph.component(4), 2);
}

TEST(CommGraph, LossesFollowTheProbabilityAndTheSeed) {
  const std::vector<Vec2> positions(8, Vec2::Zero());  // complete: 56 directed links
  CommGraph a, b;
  a.build(positions, kInf);
  b.build(positions, kInf);
  auto streams_a = streams(8, 5);
  auto streams_b = streams(8, 5);
  a.drawLosses(200, 0.3, streams_a);
  b.drawLosses(200, 0.3, streams_b);
  EXPECT_EQ(a.messages(), 200 * 56);
  // 11 200 Bernoulli(0.3) draws: standard deviation of the fraction ≈ 0.0043.
  EXPECT_NEAR(static_cast<double>(a.lostMessages()) / static_cast<double>(a.messages()), 0.3, 0.02);
  for (int round = 0; round < 200; ++round) {
    for (int link = 0; link < 56; ++link) {
      ASSERT_EQ(a.delivered(round, link), b.delivered(round, link));
    }
  }
  EXPECT_TRUE(a.delivered(200, 0));  // beyond the drawn exchanges nothing is lost

  a.drawLosses(5, 0.0, streams_a);
  EXPECT_EQ(a.lostMessages(), 0);
  EXPECT_TRUE(a.delivered(0, 0));
}

}  // namespace
}  // namespace canopy::agents::fusion
