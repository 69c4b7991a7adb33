#include "world/world.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/angles.h"

namespace canopy::world {
namespace {

WorldDef emptyWorld() {
  WorldDef def;
  def.aoi = {Vec2(-100, -100), Vec2(100, 100)};
  return def;
}

TEST(World, TargetsPassTheirWaypointsAtTheScriptedTimes) {
  WorldDef def = emptyWorld();
  // Waypoint times that are not multiples of dt, a stop, and a fast leg (20 m/s: 4 m per step of
  // 0.2 s, twice Box2D's per-step translation limit).
  def.targets.push_back({Path::throughPoints({{0.0, Vec2(0, 0)},
                                              {1.3, Vec2(2.6, 0)},
                                              {2.0, Vec2(2.6, 0)},
                                              {4.0, Vec2(2.6, 40)},
                                              {6.0, Vec2(-10, 10)}})});
  World world(def);
  const double dt = 0.2;
  for (int k = 1; k <= 40; ++k) {
    world.step(dt);
    const double t = k * dt;
    const Vec2 expected = def.targets[0].path.positionAt(t);
    // Float32 bodies: a few micrometres at tens of metres.
    EXPECT_NEAR(world.snapshot().targets[0].position.x(), expected.x(), 1e-4) << "t=" << t;
    EXPECT_NEAR(world.snapshot().targets[0].position.y(), expected.y(), 1e-4) << "t=" << t;
  }
}

TEST(World, ConstantVelocityTargetAccumulatesNoDrift) {
  WorldDef def = emptyWorld();
  def.targets.push_back({Path::constantVelocity(Vec2(-90, 3), Vec2(1.7, 0.3))});
  World world(def);
  for (int k = 0; k < 500; ++k) world.step(0.2);  // 100 s
  const Vec2 p = world.snapshot().targets[0].position;
  EXPECT_NEAR(p.x(), -90 + 170.0, 1e-4);
  EXPECT_NEAR(p.y(), 3 + 30.0, 1e-4);
}

TEST(World, CommandedUavSpeedIsClampedToVmax) {
  WorldDef def = emptyWorld();
  def.uavs.push_back({Vec2(0, 0), 0.0, YawMode::fixed, 5.0});
  World world(def);
  world.commandUav(0, Vec2(30, 40));  // |v| = 50 m/s, direction (0.6, 0.8)
  EXPECT_NEAR(world.commandedVelocity(0).norm(), 5.0, 1e-12);
  EXPECT_NEAR(world.commandedVelocity(0).x(), 3.0, 1e-12);
  world.step(1.0);
  const WorldSnapshot snap = world.snapshot();
  EXPECT_NEAR(snap.uavs[0].position.x(), 3.0, 1e-5);
  EXPECT_NEAR(snap.uavs[0].position.y(), 4.0, 1e-5);
  EXPECT_DOUBLE_EQ(snap.uavs[0].yaw, 0.0);  // fixed yaw
  world.commandUav(0, Vec2(1, 0));          // below v_max: unchanged
  EXPECT_EQ(world.commandedVelocity(0), Vec2(1, 0));
}

TEST(World, YawFollowsVelocityAndIsKeptWhileHovering) {
  WorldDef def = emptyWorld();
  def.uavs.push_back({Vec2(0, 0), 0.0, YawMode::velocity, 5.0});
  World world(def);
  world.commandUav(0, Vec2(-2, -2));  // heading −3π/4, a turn of 135° in one step
  world.step(0.2);
  EXPECT_NEAR(world.snapshot().uavs[0].yaw, -3 * kPi / 4, 1e-5);
  world.commandUav(0, Vec2::Zero());
  world.step(0.2);
  EXPECT_NEAR(world.snapshot().uavs[0].yaw, -3 * kPi / 4, 1e-5);
}

TEST(World, AabbQueryReturnsOverlappingBodiesInIdOrder) {
  WorldDef def = emptyWorld();
  def.uavs.push_back({Vec2(50, 50), 0.0, YawMode::fixed, 5.0});
  def.targets.push_back({Path::constantVelocity(Vec2(1, 1), Vec2::Zero())});
  def.targets.push_back({Path::constantVelocity(Vec2(30, 30), Vec2::Zero())});
  def.targets.push_back({Path::constantVelocity(Vec2(-2, 3), Vec2::Zero())});
  def.trees.push_back(TreeDef::disc(Vec2(4, 0), 1.0));
  def.trees.push_back(TreeDef::disc(Vec2(-40, 0), 1.0));
  World world(def);
  std::vector<BodyRef> found;
  world.queryAabb({Vec2(-5, -5), Vec2(5, 5)}, found);
  const std::vector<BodyRef> expected{
      {BodyKind::target, 0}, {BodyKind::target, 2}, {BodyKind::tree, 0}};
  EXPECT_EQ(found, expected);
}

TEST(World, OccluderPointTestIsStrict) {
  WorldDef def = emptyWorld();
  def.trees.push_back(TreeDef::disc(Vec2(0, 0), 2.0));
  def.trees.push_back(TreeDef::polygon({{10, 0}, {12, 0}, {12, 2}, {10, 2}}));
  World world(def);
  EXPECT_TRUE(world.insideOccluder(Vec2(1.9, 0)));
  EXPECT_FALSE(world.insideOccluder(Vec2(2.0, 0)));
  EXPECT_TRUE(world.insideOccluder(Vec2(11, 1)));
  EXPECT_FALSE(world.insideOccluder(Vec2(12, 1)));
  EXPECT_FALSE(world.insideOccluder(Vec2(50, 50)));
}

TEST(World, RayCastFindsTheNearestOccluderOnTheSegment) {
  WorldDef def = emptyWorld();
  def.trees.push_back(TreeDef::disc(Vec2(20, 0), 1.0));  // tree 0: far
  def.trees.push_back(TreeDef::disc(Vec2(10, 0), 1.0));  // tree 1: near
  def.trees.push_back(TreeDef::disc(Vec2(15, 5), 1.0));  // off the line
  World world(def);
  EXPECT_EQ(world.firstOccluderOnSegment(Vec2(0, 0), Vec2(30, 0)), 1);
  EXPECT_EQ(world.firstOccluderOnSegment(Vec2(30, 0), Vec2(0, 0)), 0);
  EXPECT_EQ(world.firstOccluderOnSegment(Vec2(0, 0), Vec2(8.5, 0)), std::nullopt);
  EXPECT_EQ(world.firstOccluderOnSegment(Vec2(0, 1), Vec2(30, 1)), std::nullopt);  // grazes rims
  EXPECT_EQ(world.firstOccluderOnSegment(Vec2(10.5, 0), Vec2(10.5, 0)), 1);  // zero length, inside
  EXPECT_EQ(world.firstOccluderOnSegment(Vec2(10.2, 0.2), Vec2(0, 0)), 1);   // starts inside
}

TEST(World, RayCastAgreesWithBruteForceOnARandomForest) {
  WorldDef def = emptyWorld();
  for (int i = 0; i < 40; ++i) {
    for (int j = 0; j < 40; ++j) {
      def.trees.push_back(TreeDef::disc(Vec2(-97.5 + 5 * i + (j % 3) * 0.7, -97.5 + 5 * j),
                                        0.6 + 0.05 * ((i * j) % 7)));
    }
  }
  World world(def);
  for (int s = 0; s < 200; ++s) {
    const Vec2 a(-90 + (s * 37) % 180, -90 + (s * 53) % 180);
    const Vec2 b(-90 + (s * 71) % 180, -90 + (s * 29) % 180);
    double best = 2.0;
    std::optional<int> expected;
    for (int k = 0; k < static_cast<int>(def.trees.size()); ++k) {
      const double f = segmentEntry(def.trees[k], a, b);
      if (f >= 0.0 && f < best) best = f, expected = k;
    }
    EXPECT_EQ(world.firstOccluderOnSegment(a, b), expected) << "segment " << s;
  }
}

}  // namespace
}  // namespace canopy::world
