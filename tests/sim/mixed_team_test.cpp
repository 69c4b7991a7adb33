// The built-in mixed_team scenario end to end: two UAVs and two ground robots share their tracks
// and one map of walls and trees through fusion.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/angles.h"
#include "sim/simulation.h"
#include "spec/loader.h"

namespace canopy::sim {
namespace {

TEST(MixedTeam, UavsAndGroundRobotsShareTracksAndAMapOfWallsAndTrees) {
  const spec::ScenarioSpec spec = spec::loadScenario("mixed_team");
  ASSERT_EQ(spec.uavs.size(), 4u);
  EXPECT_EQ(spec.uavs[0].body.kind, world::AgentKind::uav);
  EXPECT_EQ(spec.uavs[2].body.kind, world::AgentKind::ground);
  EXPECT_EQ(spec.uavs[2].sensor.footprint.shape, sensing::FootprintShape::sector);
  int walls = 0;
  for (const world::TreeDef& tree : spec.trees) walls += tree.shape == world::TreeShape::polygon;
  ASSERT_EQ(walls, 8);

  Simulation sim(spec);
  std::vector<long> tree_sightings(4, 0), target_sightings(4, 0);
  double robot_turn = 0.0;  // rad, the largest heading change of a ground robot in one step
  std::vector<double> heading{spec.uavs[2].body.yaw, spec.uavs[3].body.yaw};
  while (!sim.done()) {
    const StepRecord& step = sim.tick();
    for (int i = 0; i < 4; ++i) {
      for (const auto& o : step.uavs[i].scan.observations) {
        (o.label == sensing::kTreeLabel ? tree_sightings : target_sightings)[i] += 1;
      }
    }
    for (int r = 0; r < 2; ++r) {
      robot_turn = std::max(robot_turn, std::abs(wrapAngle(step.uavs[2 + r].yaw - heading[r])));
      heading[r] = step.uavs[2 + r].yaw;
    }
  }
  // Every agent saw targets and trees or walls itself.
  for (int i = 0; i < 4; ++i) {
    EXPECT_GT(target_sightings[i], 0) << spec.uavs[i].name;
    EXPECT_GT(tree_sightings[i], 0) << spec.uavs[i].name;
  }
  // The robots turned no faster than ω_max = 1 rad/s (0.2 rad a step).
  EXPECT_LE(robot_turn, 1.0 * spec.dt + 1e-5);

  const StepRecord& last = sim.lastStep();
  for (int i = 0; i < 4; ++i) {
    const agents::AgentBelief& belief = last.beliefs[i];
    // A confirmed track within 3 m of every target.
    for (std::size_t t = 0; t < spec.targets.size(); ++t) {
      double best = INFINITY;
      for (const agents::TrackEstimate& track : belief.tracks) {
        if (track.confirmed)
          best = std::min(best, (track.belief.x.head<2>() - last.targets[t].position).norm());
      }
      EXPECT_LT(best, 3.0) << spec.uavs[i].name << ", target " << spec.targets[t].name;
    }
    // Every wall in the map as a 4-vertex outline within 1 m of its true corners (a ground robot
    // measures a centre from up to 30 m away, with a bearing σ of up to √(0.3·0.1·π·30) = 1.7 m
    // per scan; the crowns' vertex offsets carry σ_r = 0.1 m).
    for (const world::TreeDef& wall : spec.trees) {
      if (wall.shape != world::TreeShape::polygon) continue;
      double best = INFINITY;
      for (const agents::TreeEstimate& tree : belief.trees) {
        if (tree.outline.vertices != 4) continue;
        double worst_corner = 0.0;
        for (int v = 0; v < 4; ++v) {
          const Vec2 corner = tree.belief.x.head<2>() + tree.outline.offsets[v];
          worst_corner = std::max(worst_corner, (corner - wall.vertices[v]).norm());
        }
        best = std::min(best, worst_corner);
      }
      EXPECT_LT(best, 1.0) << spec.uavs[i].name << ", wall at " << wall.centre.transpose();
    }
  }
}

}  // namespace
}  // namespace canopy::sim
