#pragma once
// The two-camera scene of the ground-camera and crown-height tests: a ground robot at the origin
// facing east with a 90° sector camera of 30 m, and a UAV with a 20 × 20 m downward footprint.
#include <numbers>
#include <vector>

#include "sensing/sensor.h"

namespace canopy::sensing::test {

/// def with the robot (agent 0, at the origin) and the UAV (agent 1, over uav_at); the caller
/// adds targets and trees.
inline world::WorldDef robotAndUav(const Vec2& uav_at) {
  world::WorldDef def;
  def.aoi = {Vec2(-50, -50), Vec2(50, 50)};
  world::UavDef robot;
  robot.kind = world::AgentKind::ground;
  robot.yaw_mode = world::YawMode::velocity;
  def.uavs.push_back(robot);
  world::UavDef uav;
  uav.start = uav_at;
  def.uavs.push_back(uav);
  return def;
}

/// The robot's forward camera and the UAV's downward one, by agent index.
inline std::vector<SensorDef> robotAndUavSensors() {
  std::vector<SensorDef> sensors(2);
  sensors[0].footprint.shape = FootprintShape::sector;
  sensors[0].footprint.radius = 30.0;
  sensors[0].footprint.angle = std::numbers::pi / 2;
  sensors[0].ground_level = true;
  sensors[1].footprint.size = Vec2(20, 20);
  return sensors;
}

/// One scan of `agent` in a fresh world of def, with the sensing stream of seed 1.
inline Scan senseOnce(const world::WorldDef& def, const std::vector<SensorDef>& sensors,
                      const SensingConfig& config, const std::vector<LabelId>& labels, int agent) {
  const world::World world(def);
  RandomStream rng(1, "sensing", static_cast<std::uint64_t>(agent));
  SenseScratch scratch;
  Scan out;
  sense(world, world.snapshot(), agent, sensors[agent], config, labels, rng, scratch, out);
  return out;
}

}  // namespace canopy::sensing::test
