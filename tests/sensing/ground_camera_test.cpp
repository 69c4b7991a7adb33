// A ground robot's forward camera: walls and crowns hide what stands behind them along the line
// of sight, whatever the team's occlusion model, while a UAV above sees over them.
#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>

#include "sensing/sensor.h"
#include "tests/sensing/robot_and_uav.h"

namespace canopy::sensing {
namespace {

// A robot at the origin facing east (90°, 30 m); a wall x ∈ [10, 11], y ∈ [−5, 5]; a UAV with a
// 20 × 20 m footprint over (20, 0); targets at (20, 0), (20, 8) and (20, 12); a tree of radius 1
// at (25, 0), behind the wall.
struct Street {
  world::WorldDef def;
  std::vector<SensorDef> sensors;
  std::vector<LabelId> labels{1, 1, 1};
  SensingConfig config;  // occlusion_model canopy: the UAV's model

  Street() : def(test::robotAndUav(Vec2(20, 0))), sensors(test::robotAndUavSensors()) {
    for (const Vec2& p : {Vec2(20, 0), Vec2(20, 8), Vec2(20, 12)})
      def.targets.push_back({world::Path::constantVelocity(p, Vec2::Zero())});
    def.trees = {world::TreeDef::polygon({{10, -5}, {11, -5}, {11, 5}, {10, 5}}),
                 world::TreeDef::disc({25, 0}, 1.0)};
  }

  Scan scan(int agent) const { return test::senseOnce(def, sensors, config, labels, agent); }
};

std::vector<int> trees(const Scan& scan) {
  std::vector<int> out;
  for (const Observation& o : scan.observations)
    if (o.label == kTreeLabel) out.push_back(o.truth);
  return out;
}

TEST(GroundCamera, AWallHidesATargetFromTheRobotButNotFromTheUavAbove) {
  const Street street;
  // The robot: all three targets lie in its sector (bearings 0°, 21.8°, 31.0°; ranges ≤ 23.3 m).
  // The ray to (20, 0) crosses the wall at y = 0, the ray to (20, 8) at x = 10 has y = 4 (inside
  // the wall's [−5, 5]); the ray to (20, 12) has y = 6 there and y = 6.6 at x = 11: clear.
  const Scan robot = street.scan(0);
  EXPECT_EQ(robot.in_footprint, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(robot.visible, (std::vector<int>{2}));
  // The UAV over (20, 0) sees (20, 0) and (20, 8), neither under a crown; (20, 12) is outside
  // its footprint (|y| ≤ 10).
  const Scan uav = street.scan(1);
  EXPECT_EQ(uav.in_footprint, (std::vector<int>{0, 1}));
  EXPECT_EQ(uav.visible, (std::vector<int>{0, 1}));
  // The same holds when the team's model is line of sight: the UAV's ground point (20, 0) has
  // a clear view of both.
  Street los;
  los.config.occlusion_model = OcclusionModel::line_of_sight;
  EXPECT_EQ(los.scan(1).visible, (std::vector<int>{0, 1}));
  EXPECT_EQ(los.scan(0).visible, (std::vector<int>{2}));
}

TEST(GroundCamera, TheRobotSeesTheWallButNotTheTreeBehindIt) {
  const Street street;
  // The wall's centroid (10.5, 0) is seen (its own crown is the first on the ray); the tree at
  // (25, 0) lies behind the wall. The UAV's footprint x ∈ [10, 30] holds both centres, and from
  // above crowns hide no crown.
  EXPECT_EQ(trees(street.scan(0)), (std::vector<int>{0}));
  EXPECT_EQ(trees(street.scan(1)), (std::vector<int>{0, 1}));
}

}  // namespace
}  // namespace canopy::sensing
