#pragma once
// One agent's local tracker over all labels (algorithms.md §4): NCV targets and static trees,
// a JPDAF per label, track birth, confirmation and deletion. The agent calls, every step:
//   predict(dt); update(scan, footprint, map); … the team fuses the lists …; adopt(fused lists);
//   deleteStale().
#include <cstdint>
#include <vector>

#include "agents/config.h"
#include "agents/occlusion_map.h"
#include "agents/tracking/duplicates.h"
#include "agents/tracking/jpdaf.h"
#include "agents/tracking/track.h"
#include "agents/tracking/visibility.h"
#include "sensing/footprint.h"
#include "sensing/observation.h"
#include "sensing/visibility.h"

namespace canopy::agents::tracking {

class Tracker {
 public:
  /// agent: this agent's index, the origin of the keys of the tracks it starts.
  Tracker(int agent, const TrackingConfig& config);

  /// A confirmed track with key {−1, target} for a target the scenario pre-seeds, with mean
  /// state (m, m, m/s, m/s) and P₀ = diag(config.preseed_variance). The caller checks
  /// config.preseed; label is a target label (not kTreeLabel).
  void preseed(int target, sensing::LabelId label, const Vec4& state);

  /// Every track: prior = prediction over dt (s) — NCV for targets, static for trees — and
  /// posterior = prior. A known person's prediction is bounded (agents/tracking/known_people.h)
  /// and its existence stays 1.
  void predict(double dt);

  /// The local JIPDA per label on this scan's observations (each track's P_D is P_D × its
  /// probability of being visible to the own camera, agents/tracking/visibility.h; its existence
  /// is updated, agents/tracking/existence.h) (observations only associate with
  /// tracks of their own label; tree observations with tree tracks). Then per track: `detected`,
  /// scans and hits, and the count of consecutive misses while expected visible (predicted
  /// position inside own_footprint and, for targets, not occluded in own_map; a tree's crown
  /// does not hide it). Measurements in no track's birth gate
  /// (TrackingConfig::birth_gate_probability, wider than the association gate) are born as
  /// tentative tracks with existence birth_existence. With existence confirmation a tentative
  /// track is confirmed once its existence reaches confirm_existence and dropped once it falls
  /// below delete_existence. With m_of_n a tentative track is confirmed after confirm_hits hits —
  /// scans in which Σ_j β_tj ≥ ½, i.e. it more likely than not received a measurement — within its
  /// first confirm_window scans, and dropped as soon as it can no longer be. Observations with
  /// non-finite values or a covariance that is not positive definite are ignored. `camera` says how
  /// the own camera is hidden: targets under a crown of own_map (from above), behind one on the
  /// segment from scan.sensor_position (line of sight), or (volumes) by a crown volume on the 3-D
  /// segment from scan.sensor_height above it to the head; at ground level a tree too is expected
  /// visible only when no map crown stands on the segment to the point of its crown nearest the
  /// sensor.
  void update(const sensing::Scan& scan, const sensing::Footprint& own_footprint,
              const OcclusionMap& own_map, const CameraOcclusion& camera = {});

  /// Deletes tracks with tr(P_pos) > delete_trace (or a non-finite posterior), with existence
  /// below delete_existence (existence confirmation), and, when delete_misses > 0, tracks missed
  /// that many consecutive scans while expected visible. Known people (pre-seeded keys) are never
  /// deleted but for a non-finite posterior (agents/tracking/known_people.h). Called by the agent
  /// after fusion, so it judges the fused posteriors and existences.
  void deleteStale();

  /// Merges duplicate target tracks (agents/tracking/duplicates.h): a pair whose track-to-track
  /// distance passed config.merge_gate for config.merge_scans consecutive calls becomes one. Call
  /// once per scan: the agent calls it after fusion, on the fused lists; a lone tracker after
  /// update().
  void mergeDuplicates();

  /// Replaces the tracks by the team's fused lists (TeamFusion::fuse): the same tracks with
  /// fused keys and posteriors, plus the ones adopted from neighbours. The lists are swapped
  /// in, not copied: `targets` and `trees` are left holding the replaced tracks (their storage
  /// for the next fusion to refill; their contents are not to be read).
  void adopt(std::vector<TargetTrack>&& targets, std::vector<TreeTrack>&& trees);

  const std::vector<TargetTrack>& targets() const { return targets_; }
  const std::vector<TreeTrack>& trees() const { return trees_; }

  const TrackingDiagnostics& diagnostics() const { return diagnostics_; }
  const TrackingConfig& config() const { return config_; }
  int agent() const { return agent_; }

 private:
  template <int N>
  void updateLabel(std::vector<Track<N>>& tracks, sensing::LabelId label, const sensing::Scan& scan,
                   const sensing::Footprint& own_footprint, const OcclusionMap& own_map,
                   const CameraOcclusion& camera);
  template <int N>
  void confirmOrDrop(std::vector<Track<N>>& tracks);
  template <int N>
  void deleteStale(std::vector<Track<N>>& tracks);

  int agent_;
  TrackingConfig config_;
  int next_serial_ = 0;
  std::vector<TargetTrack> targets_;
  std::vector<TreeTrack> trees_;
  TrackingDiagnostics diagnostics_;

  Jpdaf jpdaf_;
  std::vector<sensing::LabelId> labels_;  // target labels present this scan
  std::vector<int> track_ids_, obs_ids_;
  std::vector<std::uint8_t> claimed_;
  DuplicateMerger merger_;
};

}  // namespace canopy::agents::tracking
