#pragma once
// The *Def structs a World is built from. Plain values with defaults; validated by the scenario
// loader before they get here.
#include <vector>

#include "core/enum_names.h"
#include "core/types.h"
#include "world/path.h"
#include "world/tree.h"

namespace canopy::world {

enum class YawMode {
  fixed,     // ψ keeps its initial value
  velocity,  // ψ follows the direction of the velocity (kept while hovering)
};

/// What kind of agent a body is: how it moves and where its camera sits.
enum class AgentKind {
  uav,     // flies at a fixed altitude, holonomic: any velocity up to v_max, camera looking down
  ground,  // drives on the ground as a unicycle (world/unicycle.h), camera looking forward
};
inline constexpr EnumNames<AgentKind, 2> kAgentKindNames{{
    {AgentKind::uav, "uav"},
    {AgentKind::ground, "ground"},
}};

/// The bodies an agent may have (UavDef::radius), m: 0 (none) or kMinAgentRadius to
/// kMaxAgentRadius. The least is Box2D's b2_polygonRadius (2 × b2_linearSlop = 0.01 m), the skin
/// its collision keeps around every shape. Below it the arithmetic breaks before Box2D does: each
/// agent weighs 1 kg, a density of 1/(π r²) that overflows a float for r below about 1e-19 m
/// (then every position is NaN), and a sub-step may close at most half a radius (world.cpp), so
/// a radius of 1e-9 m would need ~10⁹ sub-steps per metre.
inline constexpr double kMinAgentRadius = 0.01;
inline constexpr double kMaxAgentRadius = 100.0;

/// An agent (a UAV or a ground robot): a body commanded by horizontal velocity.
struct UavDef {
  Vec2 start = Vec2::Zero();          // m
  double yaw = 0.0;                   // rad, initial heading ψ
  YawMode yaw_mode = YawMode::fixed;  // ground robots: always velocity (the heading is the body's)
  double v_max = 5.0;                 // m/s, |commanded velocity| is clamped to this
  double turn_rate = 1.0;             // rad/s, ground robots only: |ψ̇| ≤ ω_max
  AgentKind kind = AgentKind::uav;
  // m: a ground robot's body, a disc that walls, trunks and other robots stop; a UAV's keeps
  // r_i + r_j from every other UAV with a radius (UAVs fly above walls, trees and robots).
  // 0: no body, it touches nothing (the loader's default for UAVs; 0.5 m for ground robots).
  double radius = 0.0;
  // Height (issue 53), a dimension of sensing, not of the Box2D plane: the altitude z (m) moves
  // by the climb command, |ż| ≤ climb_rate (m/s), within [z_min, z_max] (m). By default fixed.
  double z = 20.0;
  double z_min = 20.0;
  double z_max = 20.0;
  double climb_rate = 0.0;
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
