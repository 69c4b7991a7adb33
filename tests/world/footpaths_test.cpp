// People who walk a footpath network (issue 52). Distances and routes worked by hand on small
// networks; "on the path" measured against the polylines as given, not the network's own graph.
#include <gtest/gtest.h>

#include <cmath>

#include "world/footpaths.h"

namespace canopy::world {
namespace {

double distanceToLines(const std::vector<std::vector<Vec2>>& lines, const Vec2& p) {
  double best = 1e300;
  for (const auto& line : lines) {
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
      const Vec2 &a = line[i], &b = line[i + 1];
      const double s = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
      best = std::min(best, (a + s * (b - a) - p).norm());
    }
  }
  return best;
}

// A 3 × 3 block street grid of 100 m blocks as separate straight footpaths (each line one row or
// column), plus a diagonal shortcut across the south-west block and a dead-end spur.
std::vector<std::vector<Vec2>> blocks() {
  std::vector<std::vector<Vec2>> lines;
  for (int k = 0; k <= 3; ++k) {
    lines.push_back({Vec2(0, 100 * k), Vec2(100, 100 * k), Vec2(200, 100 * k), Vec2(300, 100 * k)});
    lines.push_back({Vec2(100 * k, 0), Vec2(100 * k, 100), Vec2(100 * k, 200), Vec2(100 * k, 300)});
  }
  lines.push_back({Vec2(0, 0), Vec2(100, 100)});    // diagonal, 100√2 m
  lines.push_back({Vec2(300, 300), Vec2(350, 350)});  // spur to a dead end
  return lines;
}

TEST(Footpaths, JunctionsAreSharedVertices) {
  const FootpathNetwork network(blocks());
  EXPECT_EQ(network.nodeCount(), 16u + 1u);            // the grid's crossings and the spur's end
  EXPECT_EQ(network.edgeCount(), 2u * 4u * 3u + 2u);  // 24 block sides, the diagonal, the spur
}

TEST(Footpaths, ShortestRouteTakesTheShortcutAtWalkingSpeed) {
  const FootpathNetwork network(blocks());
  const double speed = 1.25;
  // From (0, 0) to (300, 300): the diagonal (100√2) then four block sides (400 m) beats the six
  // sides (600 m) of any route without it.
  const auto points = network.route(Vec2(-3, -2), Vec2(300, 300), speed);
  ASSERT_GE(points.size(), 2u);
  EXPECT_NEAR((points.front().p - Vec2(0, 0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((points.back().p - Vec2(300, 300)).norm(), 0.0, 1e-12);
  const double length = 100.0 * std::sqrt(2.0) + 400.0;
  EXPECT_NEAR(points.back().t, length / speed, 1e-9);
  // Mid-block points, from (50, 0) on the south street to (250, 300) on the north one: east and
  // north along the grid, 200 + 300 = 500 m, beats the diagonal's 50 + 100√2 + 150 + 200 = 541 m.
  const auto mid = network.route(Vec2(50, -2), Vec2(250, 305), speed);
  EXPECT_NEAR(mid.back().t * speed, 500.0, 1e-9);
  // Start and goal on the same block side: straight along it.
  const auto along = network.route(Vec2(120, 1), Vec2(180, -1), speed);
  EXPECT_NEAR(along.back().t * speed, 60.0, 1e-9);
}

TEST(Footpaths, DisconnectedPartsHaveNoRoute) {
  const FootpathNetwork network({{Vec2(0, 0), Vec2(10, 0)}, {Vec2(0, 5), Vec2(10, 5)}});
  EXPECT_THROW(network.route(Vec2(0, 0), Vec2(10, 5), 1.0), std::invalid_argument);
}

TEST(Footpaths, RandomWalkerNeverLeavesAFootpath) {
  // The stated bound: within 1 mm of a footpath at every instant (it walks the segments
  // themselves, so the distance is rounding).
  const auto lines = blocks();
  const FootpathNetwork network(lines);
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    const double speed = 1.4, duration = 1500.0;
    const Path path = Path::throughPoints(network.randomWalk(Vec2(37, 12), speed, duration, seed, 0));
    EXPECT_GE(path.points().back().t, duration);
    for (double t = 0.0; t <= duration; t += 0.05)
      ASSERT_LT(distanceToLines(lines, path.positionAt(t)), 1e-3) << "t = " << t;
    // Every leg at the walking speed, and along one footpath segment (its ends both nodes).
    for (std::size_t i = 1; i < path.points().size(); ++i) {
      const auto &a = path.points()[i - 1], &b = path.points()[i];
      EXPECT_NEAR((b.p - a.p).norm() / (b.t - a.t), speed, 1e-9);
      EXPECT_LT(distanceToLines(lines, 0.5 * (a.p + b.p)), 1e-9);
    }
  }
}

TEST(Footpaths, RandomWalkIsSeededAndTurnsBackOnlyAtDeadEnds) {
  const FootpathNetwork network(blocks());
  const auto a = network.randomWalk(Vec2(150, 100), 1.4, 600.0, 9, 0);
  const auto b = network.randomWalk(Vec2(150, 100), 1.4, 600.0, 9, 0);
  const auto c = network.randomWalk(Vec2(150, 100), 1.4, 600.0, 10, 0);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i].p, b[i].p);
  bool differs = a.size() != c.size();
  for (std::size_t i = 0; !differs && i < a.size(); ++i) differs = a[i].p != c[i].p;
  EXPECT_TRUE(differs);
  // Back along the leg it came unless at the spur's dead end (350, 350).
  for (std::size_t i = 2; i < a.size(); ++i) {
    if (a[i].p == a[i - 2].p) {
      EXPECT_EQ(a[i - 1].p, Vec2(350, 350));
    }
  }
}

}  // namespace
}  // namespace canopy::world
