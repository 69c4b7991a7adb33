// Which trunks and walls the stepped world holds (docs/design-notes.md, "Only solids near a
// robot are stepped"): every solid a robot can touch during a step is held, checked against a
// brute-force scan of every solid; the held set follows the added/removed lists; a solid two
// robots share stays until the last leaves.
#include "world/near_solids.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "core/random.h"

namespace canopy::world {
namespace {

constexpr int kTrunks = 2000;

// Discs of crown radius 2 and trunk radius 0.3 at random over [0, 200]² (0.05 per m²), a crown
// without a trunk and two walls.
std::vector<TreeDef> forest() {
  RandomStream rng(7, "near-solids-test");
  std::vector<TreeDef> trees;
  for (int k = 0; k < kTrunks; ++k) {
    TreeDef tree = TreeDef::disc(Vec2(rng.uniform(0, 200), rng.uniform(0, 200)), 2.0);
    tree.trunk_radius = 0.3;
    trees.push_back(tree);
  }
  TreeDef crown_only = TreeDef::disc(Vec2(100, 100), 2.0);  // no trunk: never held
  crown_only.trunk_radius = 0.0;
  trees.push_back(crown_only);
  // A wall 600 m long (over 64 cells of 8 m: kept out of the grid) and a short one.
  trees.push_back(TreeDef::polygon({Vec2(-200, 50), Vec2(400, 50), Vec2(400, 51), Vec2(-200, 51)}));
  trees.push_back(
      TreeDef::polygon({Vec2(150, 150), Vec2(160, 150), Vec2(160, 152), Vec2(150, 152)}));
  return trees;
}

TEST(NearSolids, EverySolidARobotCanTouchDuringTheStepIsHeld) {
  const std::vector<TreeDef> trees = forest();
  NearSolids near(trees);
  RandomStream rng(3, "near-solids-walk");
  constexpr int kRobots = 3;
  const double radius = 0.5, travel = 0.8;  // m
  std::vector<Vec2> p = {Vec2(10, 10), Vec2(190, 20), Vec2(100, 180)};
  std::vector<double> heading = {0.3, 2.0, 4.0};  // rad
  std::set<int> held;                             // what the added/removed lists say
  int recentred = 0;
  for (int step = 0; step < 2000; ++step) {
    for (int i = 0; i < kRobots; ++i) {
      std::vector<int> added, removed;
      near.update(i, p[i], radius, travel, added, removed);
      recentred += !added.empty() || !removed.empty();
      for (const int k : removed) EXPECT_EQ(held.erase(k), 1u) << "removed but not held: " << k;
      for (const int k : added) EXPECT_TRUE(held.insert(k).second) << "added twice: " << k;
    }
    for (std::size_t k = 0; k < trees.size(); ++k) {
      EXPECT_EQ(near.holds(static_cast<int>(k)), held.count(static_cast<int>(k)) == 1);
      // Brute force: a solid within radius + travel of a robot can be touched this step.
      for (int i = 0; i < kRobots; ++i) {
        if (solidDistance(trees[k], p[i]) <= radius + travel) {
          ASSERT_TRUE(near.holds(static_cast<int>(k)))
              << "robot " << i << " at (" << p[i].x() << ", " << p[i].y() << "), solid " << k;
        }
      }
    }
    EXPECT_EQ(near.heldCount(), static_cast<int>(held.size()));
    // Each robot drives 0.4 m (travel 0.8 m bounds it with room), turning by up to 0.3 rad,
    // and turns back into the forest at its edge: 800 m each over the walk.
    for (int i = 0; i < kRobots; ++i) {
      heading[i] += rng.uniform(-0.3, 0.3);
      const Vec2 next = p[i] + 0.4 * Vec2(std::cos(heading[i]), std::sin(heading[i]));
      if (next.x() < 0 || next.x() > 200 || next.y() < 0 || next.y() > 200)
        heading[i] += M_PI;
      else
        p[i] = next;
    }
  }
  EXPECT_FALSE(near.holds(kTrunks));  // the crown without a trunk
  // The walks left their neighbourhoods about 3 · 800 / (8 − 0.8) ≈ 330 times.
  EXPECT_GT(recentred, 200);
  // Never more than the solids within the neighbourhoods' boxes: ±(0.5 + 8 + 1) m around three
  // anchors hold about 3 · 19² · 0.05 ≈ 54 trunks, far from the forest's 2 000.
  EXPECT_LT(near.heldCount(), 120);
}

// One tree at the origin: a crown of radius 2 m, a trunk of 0.5 m.
TreeDef trunkAtOrigin() {
  TreeDef tree = TreeDef::disc(Vec2(0, 0), 2.0);
  tree.trunk_radius = 0.5;
  return tree;
}

TEST(NearSolids, ASharedSolidStaysUntilTheLastRobotLeaves) {
  const std::vector<TreeDef> trees = {trunkAtOrigin()};
  NearSolids near(trees);
  std::vector<int> added, removed;
  near.update(0, Vec2(3, 0), 0.5, 1.0, added, removed);
  near.update(1, Vec2(-3, 0), 0.5, 1.0, added, removed);
  EXPECT_EQ(added, std::vector<int>{0});  // the first user brings it in, the second does not
  EXPECT_TRUE(removed.empty());
  added.clear();
  // Robot 0 goes 50 m away: beyond skin 8 − travel 1, it re-centres and lets go.
  near.update(0, Vec2(50, 0), 0.5, 1.0, added, removed);
  EXPECT_TRUE(removed.empty());  // robot 1 still holds it
  EXPECT_TRUE(near.holds(0));
  near.update(1, Vec2(-50, 0), 0.5, 1.0, added, removed);
  EXPECT_EQ(removed, std::vector<int>{0});
  EXPECT_FALSE(near.holds(0));
  EXPECT_EQ(near.heldCount(), 0);
}

TEST(NearSolids, AFastRobotLooksAsFarAsItCanGo) {
  const std::vector<TreeDef> trees = {trunkAtOrigin()};
  NearSolids near(trees);
  std::vector<int> added, removed;
  // 40 m from the trunk, able to move 35 m in the step: skin 2 · 35 = 70 m reaches it.
  near.update(0, Vec2(40, 0), 0.5, 35.0, added, removed);
  EXPECT_TRUE(near.holds(0));
  // Able to move 2 m: skin 8 m does not.
  NearSolids slow(trees);
  slow.update(0, Vec2(40, 0), 0.5, 2.0, added, removed);
  EXPECT_FALSE(slow.holds(0));
}

}  // namespace
}  // namespace canopy::world
