#pragma once
// Frozen truth at one step: plain values, safe to copy and keep.
#include <vector>

#include "core/types.h"

namespace canopy::world {

struct UavState {
  Vec2 position = Vec2::Zero();  // m
  Vec2 velocity = Vec2::Zero();  // m/s, the velocity applied over the last step
  double yaw = 0.0;              // rad
};

struct TargetState {
  Vec2 position = Vec2::Zero();  // m
  Vec2 velocity = Vec2::Zero();  // m/s, the velocity applied over the last step
};

struct WorldSnapshot {
  int step = 0;       // k
  double time = 0.0;  // s, t = k·dt
  std::vector<UavState> uavs;
  std::vector<TargetState> targets;
};

}  // namespace canopy::world
