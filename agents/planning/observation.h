#pragma once
// What a learned planner sees (issue 54): one agent's observation at a planning epoch, built from
// exactly what its SMA-NBO search had — its own pose and limits, its fused tracks with their
// covariances, its teammates' latest intentions, its occlusion map near it — in its own frame
// (translated to its ground point; the world's axes; lengths in units of kLength, speeds of
// kSpeed). The one definition: `canopy imitate collect` writes these features into demonstration
// files (docs/imitation.md) and the learned planner feeds them to its network, so training and
// flight see identical inputs.
#include <span>
#include <vector>

#include "agents/gaussian.h"
#include "agents/occlusion_map.h"
#include "agents/planning/plan.h"
#include "agents/planning/uav_state.h"

namespace canopy::agents::planning {

inline constexpr double kLength = 20.0;  // m, the unit of every position feature
inline constexpr double kSpeed = 5.0;    // m/s, the unit of every velocity feature
inline constexpr int kOcclusionCells = 5;     // the occlusion patch: 5 × 5 cells ...
inline constexpr double kOcclusionCell = 8.0;  // m, ... of 8 m, centred on the agent
inline constexpr int kSelfFeatures = 6 + kOcclusionCells * kOcclusionCells;
inline constexpr int kTrackFeatures = 11;
inline constexpr int kMateFeatures = 7;

/// Features of one agent (row-major sets: one row per track, one per teammate).
struct Observation {
  // v_max/kSpeed, circumradius(φ)/kLength, tracks/10, teammates/10, own previous command
  // (x, y)/kSpeed, then per occlusion cell (row-major from the south-west) the fraction of its
  // 2 × 2 sample points strictly under a crown of the agent's planning map.
  std::vector<double> self;
  // Per track j: (px − p_i, py − p_i)/kLength, (vx, vy)/kSpeed, σ_x/kLength, σ_y/kLength, the
  // correlation P_xy/(σ_x σ_y), ln(1 + tr P_pos)/5, then (p_j + H·Δ·v_j − q)/kLength with q the
  // nearest teammate's intended ground point after H actions (nearest to p_j + H·Δ·v_j), and 1;
  // without teammates those three are 0.
  std::vector<double> tracks;
  // Per teammate k: (p_k − p_i)/kLength, its intention's first action/kSpeed, its intended
  // displacement over H actions Σ a·Δ/kLength, circumradius(φ_k)/kLength.
  std::vector<double> mates;
  int trackCount() const { return static_cast<int>(tracks.size()) / kTrackFeatures; }
  int mateCount() const { return static_cast<int>(mates.size()) / kMateFeatures; }
};

/// Agent `agent`'s observation. uavs: every UAV now; tracks and map: its own belief and planning
/// map (nullptr: nothing occludes); intentions: one plan per UAV (the agent's own entry is its
/// previous plan, shifted, for its previous command; hover when it has none), the others what it
/// holds of them; horizon H and period Δ (s) as the planner's.
Observation observe(int agent, std::span<const UavState> uavs,
                    std::span<const TargetGaussian> tracks, const OcclusionMap* map,
                    std::span<const Plan> intentions, int horizon, double period);

}  // namespace canopy::agents::planning
