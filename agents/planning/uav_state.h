#pragma once
// What the planner knows of one agent (a UAV or a ground robot) at a planning epoch: where it is,
// how it may move and what its camera sees. UAVs are heterogeneous (footprint, sensor quality,
// speed limit).
#include <optional>

#include "core/types.h"
#include "sensing/camera.h"
#include "sensing/footprint.h"
#include "sensing/noise.h"
#include "sensing/visibility.h"
#include "world/defs.h"

namespace canopy::agents::planning {

struct UavState {
  Vec2 position = Vec2::Zero();                     // m, p_{i,0}: ground point now
  double yaw = 0.0;                                 // rad, ψ now
  world::YawMode yaw_mode = world::YawMode::fixed;  // velocity: ψ follows the planned heading
  double v_max = 5.0;                               // m/s, |a_{i,m}| ≤ v_max
  world::AgentKind kind = world::AgentKind::uav;    // ground: moves as world/unicycle.h
  double turn_rate = 1.0;                           // rad/s, ground robots' ω_max
  double radius = 0.5;                              // m, its body (world::UavDef::radius)
  sensing::FootprintDef footprint;                  // φ_i relative to the UAV (m)
  sensing::SensorQuality quality;                   // α_i (dimensionless) and r0 (m) of R_i
  // What hides a target from its camera: the same model its sensor uses (sensing/visibility.h).
  sensing::OcclusionModel occlusion = sensing::OcclusionModel::canopy;
  // Height (issue 53): altitude z and its limits (m), climb rate (m/s); a camera whose footprint
  // and noise follow z (altitude_choice.h atAltitude), with α at the default altitude. Without a
  // camera the footprint and quality above hold at every altitude.
  double z = 20.0;
  double z_min = 20.0;
  double z_max = 20.0;
  double climb_rate = 0.0;
  std::optional<sensing::CameraDef> camera = std::nullopt;
  double reference_alpha = 0.3;
};

}  // namespace canopy::agents::planning
