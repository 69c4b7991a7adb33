#include "agents/agent.h"

#include <utility>

namespace canopy::agents {

Agent::Agent(int index, const TrackingConfig& config, const tracking::CameraOcclusion& camera)
    : tracker_(index, config), camera_(camera) {}

void Agent::trackLocally(double dt, const sensing::Scan& scan,
                         const sensing::Footprint& footprint) {
  tracker_.predict(dt);
  tracker_.update(scan, footprint, map_, camera_);
}

void Agent::adoptFused(std::vector<tracking::TargetTrack>&& targets,
                       std::vector<tracking::TreeTrack>&& trees) {
  tracker_.adopt(std::move(targets), std::move(trees));
  tracker_.deleteStale();
  tracker_.mergeDuplicates();  // after fusion: duplicates within the fused lists
  map_trees_.clear();
  for (const tracking::TreeTrack& tree : tracker_.trees()) {
    if (tree.status == tracking::TrackStatus::confirmed)
      map_trees_.push_back({tree.key, tree.posterior, tree.outline.mean});
  }
  map_ = OcclusionMap::fromEstimates(map_trees_, tracker_.config().tree_min_radius);
  planning_tracks_.clear();
  for (const tracking::TargetTrack& track : tracker_.targets()) {
    if (track.status == tracking::TrackStatus::confirmed)
      planning_tracks_.push_back(track.posterior);
  }
}

void Agent::writeBelief(AgentBelief& out) const {
  out.tracks.clear();
  for (const tracking::TargetTrack& track : tracker_.targets()) {
    if (track.status != tracking::TrackStatus::confirmed) continue;
    out.tracks.push_back({track.key, track.label, track.posterior, true, track.existence});
  }
  out.trees = map_trees_;
}

}  // namespace canopy::agents
