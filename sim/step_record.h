#pragma once
// One step of a run as one value: what Simulation::tick() produces and every observer (record,
// summary, trial collector, frames, rendered coverage) reads. Plain structs and vectors, so a
// binding or a custom controller can read it field by field: the truth (each UAV's pose and
// command, each target's state), each UAV's footprint and scan, each agent's belief and counts,
// and the team's plan when the step was a planning epoch.
#include <cstddef>
#include <optional>
#include <vector>

#include "agents/belief.h"
#include "agents/fusion/fusion_diagnostics.h"
#include "agents/planning/team_planner.h"
#include "agents/tracking/track.h"
#include "core/types.h"
#include "sensing/footprint.h"
#include "sensing/observation.h"
#include "world/snapshot.h"

namespace canopy::sim {

/// One UAV at the step: its true pose, the command it was given, where its camera looked and
/// what the camera reported.
struct UavRecord {
  Vec2 position = Vec2::Zero();  // m, ground point p_i
  double yaw = 0.0;              // rad, ψ_i
  Vec2 velocity = Vec2::Zero();  // m/s, flown over the step that led here
  /// m/s, the planner's or path's command for the next step, clamped to v_max (what the record
  /// writes as "cmd"). An external command (Simulation::commandNext) set after the tick replaces
  /// it in flight and is not in it; what was flown is the next step's `velocity`.
  Vec2 command = Vec2::Zero();
  // What its body touched during the step that led here (trunks and walls by tree index, other
  // agents by index), sorted, and how many of those it did not touch the step before.
  std::vector<world::BodyRef> contacts{};
  int contacts_begun = 0;
  sensing::Footprint footprint;  // φ_i at this pose
  sensing::Scan scan;            // scan.uav is this UAV's index
  // Height (issue 53): its altitude (m), the climb flown over the step that led here and the
  // climb command for the next step (m/s, clamped to the climb rate). `altitude`: the UAV flies
  // at a chosen altitude (its scenario gives one), so the record writes "z".
  double z = 0.0;
  double climb = 0.0;
  double climb_command = 0.0;
  bool altitude = false;
};

/// One target's truth at the step.
struct TargetRecord {
  Vec2 position = Vec2::Zero();  // m
  Vec2 velocity = Vec2::Zero();  // m/s, over the step that led here
  bool occluded = false;         // strictly under some tree crown
};

/// One agent's bookkeeping after the step's fusion.
struct AgentCounts {
  std::size_t tracks = 0;                          // target tracks held, tentative ones included
  std::size_t trees_in_map = 0;                    // discs of its occlusion map Ŵ_i
  agents::tracking::TrackingDiagnostics tracking;  // totals since the start
};

struct StepRecord {
  int step = 0;                       // k
  double time = 0.0;                  // s, t = k·dt
  std::vector<UavRecord> uavs;        // by UAV index
  std::vector<TargetRecord> targets;  // by target index
  /// Per agent (agent i flies UAV i): fused tracks, occlusion map and planned path, after this
  /// step's fusion.
  std::vector<agents::AgentBelief> beliefs;
  std::vector<AgentCounts> counts;                 // per agent
  agents::fusion::FusionDiagnostics fusion;        // the team's, totals since the start
  agents::planning::MessageCounts intentions;      // the team's, totals since the start
  std::optional<agents::planning::TeamPlan> plan;  // made at this step, on planning epochs
};

/// The truth of `record` as the world's snapshot type, for code written against it (the
/// renderer). Overwrites `out`, reusing its storage.
void truthSnapshot(const StepRecord& record, world::WorldSnapshot& out);

}  // namespace canopy::sim
