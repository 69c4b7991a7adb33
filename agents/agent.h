#pragma once
// One UAV's tracking stack: its local tracker and the dynamic occlusion map Ŵ_i built from its
// fused tree tracks. Never sees the world: only scans, and (through the team) its neighbours.
#include <vector>

#include "agents/belief.h"
#include "agents/config.h"
#include "agents/occlusion_map.h"
#include "agents/tracking/tracker.h"
#include "sensing/footprint.h"
#include "sensing/observation.h"

namespace canopy::agents {

class Agent {
 public:
  /// camera: what hides things from this agent's camera, as its tracker expects them.
  Agent(int index, const TrackingConfig& config, const tracking::CameraOcclusion& camera = {});

  /// A confirmed track on a target the scenario pre-seeds (Tracker::preseed).
  void preseed(int target, sensing::LabelId label, const Vec4& state) {
    tracker_.preseed(target, label, state);
  }
  /// Predicts every track over dt (s) and runs the local JPDAF on this step's scan. The map
  /// used to judge expected misses is the one from the end of the previous step.
  void trackLocally(double dt, const sensing::Scan& scan, const sensing::Footprint& footprint);
  /// After the team's fusion: takes its fused lists as its own (Tracker::adopt: swapped in, the
  /// arguments are left with the replaced lists' storage), deletes stale tracks, merges
  /// duplicates (Tracker::mergeDuplicates) and rebuilds Ŵ_i
  /// from the confirmed trees.
  void adoptFused(std::vector<tracking::TargetTrack>&& targets,
                  std::vector<tracking::TreeTrack>&& trees);

  /// Confirmed target tracks' posteriors: what the planner plans on.
  const std::vector<TargetGaussian>& planningTracks() const { return planning_tracks_; }
  const OcclusionMap& map() const { return map_; }
  /// Confirmed target tracks and the map's trees, as plain values, into `out` (its storage
  /// reused; planned_path is left to the team, which plans).
  void writeBelief(AgentBelief& out) const;

  const tracking::Tracker& tracker() const { return tracker_; }

 private:
  tracking::Tracker tracker_;
  tracking::CameraOcclusion camera_;
  OcclusionMap map_;
  std::vector<TreeEstimate> map_trees_;          // the confirmed tree tracks behind map_
  std::vector<TargetGaussian> planning_tracks_;  // confirmed target tracks' posteriors
};

}  // namespace canopy::agents
