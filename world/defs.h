#pragma once
// The *Def structs a World is built from. Plain values with defaults; validated by the scenario
// loader before they get here.
#include <vector>

#include "core/types.h"
#include "world/path.h"
#include "world/tree.h"

namespace canopy::world {

enum class YawMode {
  fixed,     // ψ keeps its initial value
  velocity,  // ψ follows the direction of the velocity (kept while hovering)
};

/// A UAV: a kinematic body at fixed altitude, commanded by horizontal velocity.
struct UavDef {
  Vec2 start = Vec2::Zero();  // m
  double yaw = 0.0;           // rad, initial heading ψ
  YawMode yaw_mode = YawMode::fixed;
  double v_max = 5.0;  // m/s, |commanded velocity| is clamped to this
};

/// A target (OOI): a kinematic body driven by velocity along a scripted path.
struct TargetDef {
  Path path;
};

struct WorldDef {
  Aabb aoi;  // the area of interest (m)
  std::vector<UavDef> uavs;
  std::vector<TargetDef> targets;
  std::vector<TreeDef> trees;
};

}  // namespace canopy::world
