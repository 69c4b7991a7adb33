// Crowns with heights (issue 53) under the `volumes` occlusion model: a walker (head at 1.7 m)
// under a crown whose base is 3 m is seen by a ground robot's camera at 0.5 m beside it and not by
// a UAV straight above; a crown from the ground up hides it from both; walls with a height hide a
// walker from a robot but not from a UAV looking over them. Each verdict by hand from the geometry.
#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>

#include "sensing/sensor.h"
#include "tests/sensing/robot_and_uav.h"
#include "world/tree.h"

namespace canopy::sensing {
namespace {

bool contains(const std::vector<int>& v, int x) { return std::find(v.begin(), v.end(), x) != v.end(); }

// A robot at the origin facing east (90° sector, 30 m); a UAV at 20 m over (12, 0) with a
// 20 × 20 m footprint; a walker standing at (12, 0); one tree of radius 3 at (12, 0).
struct Grove {
  world::WorldDef def;
  std::vector<SensorDef> sensors;
  std::vector<LabelId> labels{1};
  SensingConfig config;

  explicit Grove(world::TreeDef tree)
      : def(test::robotAndUav(Vec2(12, 0))), sensors(test::robotAndUavSensors()) {
    config.occlusion_model = OcclusionModel::volumes;
    def.targets.push_back({world::Path::constantVelocity(Vec2(12, 0), Vec2::Zero())});
    def.trees = {std::move(tree)};
  }

  Scan scan(int agent) const { return test::senseOnce(def, sensors, config, labels, agent); }
};

world::TreeDef crown(double base, double top) {
  world::TreeDef tree = world::TreeDef::disc(Vec2(12, 0), 3.0);
  tree.base = base;
  tree.top = top;
  return tree;
}

TEST(CrownHeight, GroundCameraSeesUnderAHighCrownAndTheUavAboveDoesNot) {
  // Robot: the sight line runs from 0.5 m to 1.7 m, below the base at 3 m: clear. UAV: straight
  // down from 20 m to 1.7 m inside the crown's outline, through [3, 10] m: hidden.
  const Grove grove(crown(3.0, 10.0));
  EXPECT_EQ(grove.sensors[1].camera, std::nullopt);
  const Scan robot = grove.scan(0);
  EXPECT_TRUE(contains(robot.in_footprint, 0));
  EXPECT_TRUE(contains(robot.visible, 0));
  const Scan uav = grove.scan(1);
  EXPECT_TRUE(contains(uav.in_footprint, 0));
  EXPECT_FALSE(contains(uav.visible, 0));
}

TEST(CrownHeight, ACrownFromTheGroundHidesTheWalkerFromBoth) {
  const Grove grove(crown(0.0, std::numeric_limits<double>::infinity()));  // the default
  EXPECT_FALSE(contains(grove.scan(0).visible, 0));
  EXPECT_FALSE(contains(grove.scan(1).visible, 0));
}

TEST(CrownHeight, ALowCrownHidesFromTheRobotOnly) {
  // A bush from 0 to 1 m: the robot's line from 0.5 m enters the outline at x = 9, at height
  // 0.5 + 1.2 · 9/12 = 1.4 m, above the bush: clear. A bush to 1.5 m: hidden (1.4 < 1.5). The UAV
  // looks down through 1.7 … 20 m, all above the bush: clear.
  EXPECT_TRUE(contains(Grove(crown(0.0, 1.0)).scan(0).visible, 0));
  EXPECT_FALSE(contains(Grove(crown(0.0, 1.5)).scan(0).visible, 0));
  EXPECT_TRUE(contains(Grove(crown(0.0, 1.5)).scan(1).visible, 0));
}

TEST(CrownHeight, BlocksSightByHand) {
  const world::TreeDef tree = crown(3.0, 10.0);
  // Horizontal sight at 5 m through the crown: hidden; at 2 m and 11 m: clear.
  EXPECT_TRUE(world::blocksSight(tree, Vec2(0, 0), 5.0, Vec2(30, 0), 5.0));
  EXPECT_FALSE(world::blocksSight(tree, Vec2(0, 0), 2.0, Vec2(30, 0), 2.0));
  EXPECT_FALSE(world::blocksSight(tree, Vec2(0, 0), 11.0, Vec2(30, 0), 11.0));
  // From (0, 0) at 0 m to (30, 0) at 30 m: inside the outline over x ∈ [9, 15], heights 9 … 15,
  // which meet (3, 10): hidden. Starting at 12 m: heights 12 + 18·0.3 … 12 + 18·0.5 = 17.4 … 21
  // above the top: clear.
  EXPECT_TRUE(world::blocksSight(tree, Vec2(0, 0), 0.0, Vec2(30, 0), 30.0));
  EXPECT_FALSE(world::blocksSight(tree, Vec2(0, 0), 12.0, Vec2(30, 0), 30.0));
  // A line that misses the outline in the plane is never hidden.
  EXPECT_FALSE(world::blocksSight(tree, Vec2(0, 5), 5.0, Vec2(30, 5), 5.0));
}

TEST(CrownHeight, AWallWithAHeightHidesFromTheRobotNotFromAbove) {
  // A wall x ∈ [6, 7] 2 m high between the robot and the walker: the robot's line is at
  // 0.5 + 1.2 · 6/12 = 1.1 m there, below 2 m: hidden. The UAV over (12, 0) looks straight down,
  // beside the wall: clear.
  world::TreeDef wall = world::TreeDef::polygon({{6, -5}, {7, -5}, {7, 5}, {6, 5}});
  wall.top = 2.0;
  const Grove grove(wall);
  EXPECT_FALSE(contains(grove.scan(0).visible, 0));
  EXPECT_TRUE(contains(grove.scan(1).visible, 0));
}

}  // namespace
}  // namespace canopy::sensing
