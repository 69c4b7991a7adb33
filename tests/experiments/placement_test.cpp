#include "experiments/placement.h"

#include <gtest/gtest.h>

#include <numbers>

#include "spec/loader.h"

namespace canopy::experiments {
namespace {

TEST(Placement, MirrorMapsEveryPositionVelocityAndHeading) {
  const spec::ScenarioSpec spec = spec::loadScenario("joint_effect_v2");
  const spec::ScenarioSpec m = placed(spec, Placement::mirrorX());
  // Hand-derived from joint_effect_v2.json: I from (−20, 4) at (2.5, 0) m/s; the tree at (−11, 4).
  EXPECT_EQ(m.targets[0].path.start(), Vec2(20, 4));
  EXPECT_EQ(m.targets[0].path.velocity(), Vec2(-2.5, 0));
  EXPECT_EQ(m.trees[0].centre, Vec2(11, 4));
  EXPECT_EQ(m.trees[0].radius, 3.5);
  EXPECT_EQ(m.uavs[1].body.start, Vec2(20, -4));
  EXPECT_NEAR(m.uavs[0].body.yaw, std::numbers::pi, 1e-12);  // ψ = 0 mirrored points west
  EXPECT_EQ(m.aoi.lo, Vec2(-40, -30));
  EXPECT_EQ(m.aoi.hi, Vec2(40, 30));
}

TEST(Placement, RotationAndScalesKeepTimingConsistent) {
  const spec::ScenarioSpec spec = spec::loadScenario("trajectory_handover");
  Placement p = Placement::rotation(0.5 * std::numbers::pi);
  p.distance_scale = 1.1;
  p.speed_scale = 0.9;
  const spec::ScenarioSpec r = placed(spec, p);
  // I walks (−9, 3) → (−3, 27) in 12 s; ×1.1 and rotated by 90°: (−3.3, −9.9) → (−29.7, −3.3),
  // at 0.9 of the speed: in 12 / 0.9 s.
  const double L = spec.duration / 0.9;
  EXPECT_NEAR(r.duration, L, 1e-12);
  EXPECT_LT((r.targets[0].path.positionAt(0) - Vec2(-3.3, -9.9)).norm(), 1e-9);
  EXPECT_LT((r.targets[0].path.positionAt(L) - Vec2(-29.7, -3.3)).norm(), 1e-9);
  EXPECT_NEAR(r.uavs[0].sensor.footprint.size.x(), 1.1 * spec.uavs[0].sensor.footprint.size.x(),
              1e-12);
}

TEST(Placement, PolygonsStayCounterClockwiseUnderAReflection) {
  spec::ScenarioSpec spec = spec::loadScenario("demo");
  spec.trees = {world::TreeDef::polygon({{0, 0}, {4, 0}, {4, 2}, {0, 2}})};
  const spec::ScenarioSpec m = placed(spec, Placement::mirrorX());
  EXPECT_GT(world::signedArea(m.trees[0].vertices), 0.0);
  EXPECT_LT((m.trees[0].centre - Vec2(-2, 1)).norm(), 1e-12);
}

}  // namespace
}  // namespace canopy::experiments

namespace canopy::experiments {
namespace {

TEST(Placement, HeightsStayAndACamerasFootprintScales) {
  // Issue 53: altitude_tradeoff's crowns stand 4-12 m high and its cameras see 16 × 12 m at 20 m;
  // distances × 1.1 keep the heights and make that footprint 17.6 × 13.2 m.
  const spec::ScenarioSpec spec = spec::loadScenario("altitude_tradeoff");
  Placement p = Placement::rotation(0.0);
  p.distance_scale = 1.1;
  const spec::ScenarioSpec s = placed(spec, p);
  ASSERT_FALSE(s.trees.empty());
  for (const world::TreeDef& tree : s.trees) {
    EXPECT_EQ(tree.base, 4.0);
    EXPECT_EQ(tree.top, 12.0);
  }
  ASSERT_TRUE(s.uavs[0].sensor.camera);
  EXPECT_NEAR(s.uavs[0].sensor.camera->nadir_size.x(), 17.6, 1e-12);
  EXPECT_NEAR(s.uavs[0].sensor.camera->nadir_size.y(), 13.2, 1e-12);
}

}  // namespace
}  // namespace canopy::experiments
