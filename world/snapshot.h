#pragma once
// Frozen truth at one step: plain values, safe to copy and keep.
#include <vector>

#include "core/types.h"

namespace canopy::world {

/// What a body of the world is: an agent (a UAV or a ground robot), a target, a tree's crown, or
/// a tree's solid part, its trunk or (a polygon without a trunk) the whole wall (world/tree.h).
enum class BodyKind { uav, target, tree, trunk, wall };

/// Our own id of a body: its kind and its index in the WorldDef's list (uavs, targets, trees).
struct BodyRef {
  BodyKind kind = BodyKind::target;
  int index = 0;
  friend bool operator==(const BodyRef&, const BodyRef&) = default;
  friend bool operator<(const BodyRef& x, const BodyRef& y) {
    return x.kind != y.kind ? x.kind < y.kind : x.index < y.index;
  }
};

struct UavState {
  Vec2 position = Vec2::Zero();  // m
  Vec2 velocity = Vec2::Zero();  // m/s, the velocity applied over the last step
  double yaw = 0.0;              // rad
  // What the body touched during the step that led here (a trunk or wall by its tree's index,
  // another agent by its index), sorted; empty for a body clear of everything.
  std::vector<BodyRef> contacts{};
  int contacts_begun = 0;  // of those, the ones it did not touch during the step before
  double z = 0.0;          // m, altitude (world::UavDef::z and its climbs)
  double climb = 0.0;      // m/s, the climb rate applied over the last step
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
