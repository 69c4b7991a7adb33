// Line of sight, one model everywhere: the planner's map answers "does a tree lie between this
// UAV and that point?" exactly as sensing's Box2D ray cast does, and the NBO cost uses it.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "agents/occlusion_map.h"
#include "agents/planning/nominal_cost.h"
#include "core/random.h"
#include "world/world.h"

namespace canopy::agents::planning {
namespace {

std::vector<world::TreeDef> layout() {
  return {world::TreeDef::disc({5, 0}, 1.5), world::TreeDef::disc({-6, 4}, 2.0),
          world::TreeDef::disc({-4, -9}, 0.8),
          // a wall 2 m thick and 10 m long
          world::TreeDef::polygon({{10, -5}, {12, -5}, {12, 5}, {10, 5}})};
}

TEST(LineOfSight, MapAgreesWithHandDerivedCases) {
  const OcclusionMap map(layout());
  // The disc at (5, 0), r = 1.5, on the x axis: entered at x = 3.5.
  EXPECT_TRUE(map.blocksSegment({0, 0}, {10, 0}));
  EXPECT_FALSE(map.blocksSegment({0, 0}, {3, 0}));  // ends before the crown
  // Towards (10, 4): the line 0.4 x − y = 0 passes 0.4·5/√1.16 = 1.857 m from the centre > 1.5.
  EXPECT_FALSE(map.blocksSegment({0, 0}, {10, 4}));
  // Towards (10, 3): 0.3·5/√1.09 = 1.437 m < 1.5.
  EXPECT_TRUE(map.blocksSegment({0, 0}, {10, 3}));
  // Behind the wall only: from (8, 4) to (14, 4) crosses x ∈ [10, 12] at y = 4 < 5.
  EXPECT_TRUE(map.blocksSegment({8, 4}, {14, 4}));
  EXPECT_FALSE(map.blocksSegment({8, 6}, {14, 6}));  // above the wall's end
  // A viewer under a crown sees nothing; a zero-length segment is the point test.
  EXPECT_TRUE(map.blocksSegment({-6, 4}, {-20, 20}));
  EXPECT_TRUE(map.blocksSegment({5, 0}, {5, 0}));
  EXPECT_FALSE(map.blocksSegment({0, 0}, {0, 0}));
}

// The grid index only narrows which trees are tried: on random maps (dense and sparse, discs and
// polygons, small and large crowns, so that cells are narrow or wide) and random segments (long
// and short, near-horizontal, near-vertical, ending on cell boundaries, reaching past the map),
// the map answers as trying every tree does.
TEST(LineOfSight, MapEqualsTryingEveryTree) {
  RandomStream rng(41, "line-of-sight-index-test");
  int blocked = 0, clear = 0;
  for (int map_index = 0; map_index < 40; ++map_index) {
    std::vector<world::TreeDef> trees;
    const int count = map_index % 4 == 0 ? 3 : 60 + map_index * 10;
    const double spread = map_index % 3 == 0 ? 20.0 : 150.0;
    const double size = map_index % 5 == 0 ? 8.0 : 1.5;
    for (int k = 0; k < count; ++k) {
      const Vec2 c(rng.uniform(-spread, spread), rng.uniform(-spread, spread));
      const double r = rng.uniform(0.2, 1.0) * size;
      if (k % 3 == 0) {
        trees.push_back(world::TreeDef::polygon(
            {c + Vec2(-r, -0.5 * r), c + Vec2(r, -0.5 * r), c + Vec2(0.3 * r, r)}));
      } else {
        trees.push_back(world::TreeDef::disc(c, r));
      }
    }
    const OcclusionMap map(trees);
    for (int k = 0; k < 400; ++k) {
      const double reach = spread * 1.3;
      const Vec2 a(rng.uniform(-reach, reach), rng.uniform(-reach, reach));
      Vec2 b(rng.uniform(-reach, reach), rng.uniform(-reach, reach));
      if (k % 4 == 1) b = a + Vec2(rng.uniform(-15, 15), rng.uniform(-1e-9, 1e-9));  // ~horizontal
      if (k % 4 == 2) b = a + Vec2(rng.uniform(-1e-9, 1e-9), rng.uniform(-15, 15));  // ~vertical
      if (k % 8 == 3) b = Vec2(std::round(b.x()), std::round(b.y()));  // on round coordinates
      bool any = false;
      for (const world::TreeDef& tree : trees) any = any || world::segmentEntry(tree, a, b) >= 0.0;
      if ((b - a).squaredNorm() < 1e-12) continue;  // the point test, covered elsewhere
      ASSERT_EQ(map.blocksSegment(a, b), any) << "map " << map_index << ", segment ("
                                              << a.transpose() << ") → (" << b.transpose() << ")";
      (any ? blocked : clear) += 1;
    }
  }
  EXPECT_GT(blocked, 2000);  // both answers are exercised
  EXPECT_GT(clear, 2000);
}

TEST(LineOfSight, PlannerMapEqualsSensingOnAGridOfViewersAndTargets) {
  world::WorldDef def;
  def.aoi = {Vec2(-20, -20), Vec2(20, 20)};
  def.trees = layout();
  const world::World world(def);
  const OcclusionMap map(def.trees);
  int pairs = 0, blocked = 0;
  for (double vx = -18; vx <= 18; vx += 3) {
    for (double vy = -18; vy <= 18; vy += 3) {
      for (double tx = -19; tx <= 19; tx += 2.5) {
        for (double ty = -19; ty <= 19; ty += 2.5) {
          const Vec2 viewer(vx, vy), target(tx, ty);
          const bool sensing = world.firstOccluderOnSegment(viewer, target).has_value();
          ASSERT_EQ(map.blocksSegment(viewer, target), sensing)
              << "viewer (" << vx << ", " << vy << "), target (" << tx << ", " << ty << ")";
          ++pairs;
          blocked += sensing;
        }
      }
    }
  }
  // Not a vacuous agreement: a good share of the pairs is blocked, most are not.
  EXPECT_GT(blocked, pairs / 20);
  EXPECT_LT(blocked, pairs / 2);
}

// One static target at (6, 0), P₀ = I₄, σ_a = 1, Δ = 1, H = 1, α = 0.3, r0 = 2 m, 20 × 20 m
// footprints; a disc (3, 0), r = 1, between it and a UAV at the origin. Seen from 6 m away
// (along either axis), R has 0.3·0.1·6 = 0.18 along the range and 0.18·π across it, and each axis
// is a scalar update of p⁻ = 2.25: tr P₁ = Σ 2.25 r / (2.25 + r). Unseen, tr P⁻₁ = 4.5.
constexpr double kPi = std::numbers::pi;
const double kSeen = 2.25 * 0.18 / (2.25 + 0.18) + 2.25 * 0.18 * kPi / (2.25 + 0.18 * kPi);

UavState uavAt(Vec2 p, sensing::OcclusionModel model) {
  UavState u;
  u.position = p;
  u.occlusion = model;
  return u;
}

double costOf(const std::vector<UavState>& uavs, std::vector<int> free, bool terminal) {
  const OcclusionMap map({world::TreeDef::disc({3, 0}, 1.0)});
  TargetGaussian target;
  target.x << 6, 0, 0, 0;
  target.P = Mat4::Identity();
  const std::vector<TargetGaussian> targets{target};
  CostSettings s;
  s.horizon = 1;
  s.terminal_penalty = terminal;
  const std::vector<Plan> plans(uavs.size(), hoverPlan(1));
  NominalCost cost;
  cost.prepare(PlanningProblem{targets, uavs, &map, s}, free, plans);
  const std::vector<Vec2> hover(free.size(), Vec2::Zero());
  return cost.evaluate(hover);
}

TEST(LineOfSight, TheCostHidesATargetBehindATreeFromThatUavOnly) {
  using enum sensing::OcclusionModel;
  // Looking down (canopy model), the tree is beside the target: seen.
  EXPECT_NEAR(costOf({uavAt({0, 0}, canopy)}, {0}, false), kSeen, 1e-12);
  // Along the line of sight the tree is in the way: unseen, and, not under a crown, the target
  // draws the terminal penalty w·|p − z|·tr = 0.5·6·4.5.
  EXPECT_NEAR(costOf({uavAt({0, 0}, line_of_sight)}, {0}, false), 4.5, 1e-12);
  EXPECT_NEAR(costOf({uavAt({0, 0}, line_of_sight)}, {0}, true), 4.5 + 0.5 * 6 * 4.5, 1e-12);
  // A teammate at (6, 6) sees it past the tree, free or fixed; the blocked UAV adds nothing.
  const std::vector<UavState> two{uavAt({0, 0}, line_of_sight), uavAt({6, 6}, line_of_sight)};
  EXPECT_NEAR(costOf(two, {0, 1}, true), kSeen, 1e-12);
  EXPECT_NEAR(costOf(two, {0}, true), kSeen, 1e-12);
  EXPECT_NEAR(costOf(two, {1}, true), kSeen, 1e-12);
  // Blocked as a fixed UAV too.
  const std::vector<UavState> blocked_fixed{uavAt({0, 0}, line_of_sight),
                                            uavAt({-30, -30}, line_of_sight)};
  EXPECT_NEAR(costOf(blocked_fixed, {1}, false), 4.5, 1e-12);
}

}  // namespace
}  // namespace canopy::agents::planning
