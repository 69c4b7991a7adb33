#pragma once
// What the planner knows of one agent (a UAV or a ground robot) at a planning epoch: where it is,
// how it may move and what its camera sees. UAVs are heterogeneous (footprint, sensor quality,
// speed limit).
#include "core/types.h"
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
};

}  // namespace canopy::agents::planning
