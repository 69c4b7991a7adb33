#include "agents/tracking/tracker.h"

#include <algorithm>

#include "agents/tracking/existence.h"
#include "agents/tracking/known_people.h"
#include "agents/tracking/measurement_model.h"
#include "agents/tracking/missed_detection.h"
#include "agents/tracking/motion_model.h"

namespace canopy::agents::tracking {
namespace {

// Σ_j β_tj from which a scan counts as a hit for confirmation.
constexpr double kHitProbability = 0.5;
// β_tj from which measurement j counts as one that updated track t (the duplicate test).
constexpr double kSharedProbability = 0.1;

// Expected visible: the predicted position lies in the own footprint and is not hidden from the
// own camera by the own occlusion map — for targets under a crown (from above) or behind one
// (line of sight from the sensor). A tree's centre lies inside its own crown and a camera from
// above sees every crown, so there trees only need the footprint; at ground level a tree is
// hidden when a crown of the map stands on the segment to the point of its crown nearest the
// sensor (its own crown is only touched there, which does not count; a polygon's crown is taken
// as its disc of equal area, the track's radius).
template <int N>
bool expectedVisible(const Track<N>& track, const sensing::Footprint& footprint,
                     const OcclusionMap& map, const CameraOcclusion& camera, const Vec2& sensor,
                     double sensor_height) {
  const Vec2 position = track.prior.x.template head<2>();
  if constexpr (N == 3) {
    if (!footprint.contains(position)) return false;
    if (!camera.ground_level) return true;
    const Vec2 offset = position - sensor;
    const double distance = offset.norm();
    const double radius = std::max(track.prior.x(2), 0.0);
    if (distance <= radius) return true;  // the sensor under the crown: it fills the view
    return !map.blocksSegment(sensor, position - (radius / distance) * offset);
  } else {
    return targetVisible(position, footprint, map, camera, sensor, sensor_height);
  }
}

// P(visible) of a track this scan: for targets over its position uncertainty (five sigma
// points, agents/tracking/visibility.h); for trees the centre's verdict (a map's crown is seen
// whole or not at all).
template <int N>
double visibility(const Track<N>& track, const sensing::Footprint& footprint,
                  const OcclusionMap& map, const CameraOcclusion& camera, const Vec2& sensor,
                  double sensor_height) {
  if constexpr (N == 3) {
    return expectedVisible(track, footprint, map, camera, sensor, sensor_height) ? 1.0 : 0.0;
  } else {
    return visibleProbability(track.prior.x.template head<2>(),
                              track.prior.P.template topLeftCorner<2, 2>(), footprint, map, camera,
                              sensor, sensor_height);
  }
}

}  // namespace

Tracker::Tracker(int agent, const TrackingConfig& config) : agent_(agent), config_(config) {}

void Tracker::preseed(int target, sensing::LabelId label, const Vec4& state) {
  TargetTrack track;
  track.key = {-1, target};
  track.label = label;
  track.posterior.x = state;
  track.posterior.P = config_.preseed_variance.asDiagonal();
  track.prior = track.posterior;
  track.status = TrackStatus::confirmed;
  targets_.push_back(track);
}

void Tracker::predict(double dt) {
  const double survival = scanSurvival(config_.survival_probability, dt);  // p_S over dt
  for (TargetTrack& track : targets_) {
    track.prior = predictNcv(track.posterior, dt, config_.sigma_a);
    track.strongest_detection = -1;
    const bool known = isKnown(track.key);
    if (known) {
      boundKnownPerson(track.prior, config_.area, config_.walk_speed,
                       isLost(track.prior, config_.delete_trace));
    }
    track.posterior = track.prior;
    // ψ = p_S r; a known person does not leave: p_S = 1, r = 1.
    track.existence_prior = known ? 1.0 : survival * track.existence;
    track.existence = track.existence_prior;
  }
  for (TreeTrack& track : trees_) {  // trees do not go away: p_S = 1
    track.prior = predictStatic(track.posterior);
    track.posterior = track.prior;
    track.existence_prior = track.existence;
  }
}

void Tracker::update(const sensing::Scan& scan, const sensing::Footprint& own_footprint,
                     const OcclusionMap& own_map, const CameraOcclusion& camera) {
  labels_.clear();
  for (const TargetTrack& track : targets_) {
    if (track.label != sensing::kTreeLabel) labels_.push_back(track.label);
  }
  for (const sensing::Observation& o : scan.observations) {
    if (o.label != sensing::kTreeLabel) labels_.push_back(o.label);
  }
  std::sort(labels_.begin(), labels_.end());
  labels_.erase(std::unique(labels_.begin(), labels_.end()), labels_.end());
  for (const sensing::LabelId label : labels_) {
    updateLabel(targets_, label, scan, own_footprint, own_map, camera);
  }
  updateLabel(trees_, sensing::kTreeLabel, scan, own_footprint, own_map, camera);
  confirmOrDrop(targets_);
  confirmOrDrop(trees_);
}

template <int N>
void Tracker::updateLabel(std::vector<Track<N>>& tracks, sensing::LabelId label,
                          const sensing::Scan& scan, const sensing::Footprint& own_footprint,
                          const OcclusionMap& own_map, const CameraOcclusion& camera) {
  using Model = MeasurementModel<N>;
  track_ids_.clear();
  for (int k = 0; k < static_cast<int>(tracks.size()); ++k) {
    if (tracks[k].label == label) track_ids_.push_back(k);
  }
  obs_ids_.clear();
  for (int l = 0; l < static_cast<int>(scan.observations.size()); ++l) {
    const sensing::Observation& o = scan.observations[l];
    if (o.label == label && Model::valid(o)) obs_ids_.push_back(l);
  }
  for (const int k : track_ids_) {
    tracks[k].visibility = visibility(tracks[k], own_footprint, own_map, camera,
                                      scan.sensor_position, scan.sensor_height);
  }
  claimed_.resize(obs_ids_.size());
  jpdaf_.step<N>(tracks, track_ids_, scan.observations, obs_ids_, config_, claimed_, diagnostics_);

  for (int k = 0; k < static_cast<int>(track_ids_.size()); ++k) {
    Track<N>& track = tracks[track_ids_[k]];
    ++track.scans;
    // A hit is a scan in which the track more likely than not received one of the measurements,
    // not merely gated one: a track born (from clutter, say) beside an established track shares
    // the target's next measurements with it but mostly loses them, so it is dropped instead of
    // confirmed as a duplicate.
    if (jpdaf_.detectionProbability(k) >= kHitProbability) ++track.hits;
    if constexpr (N == 4) {
      const int l = jpdaf_.strongestMeasurement(k, kSharedProbability);
      track.strongest_detection = l >= 0 ? obs_ids_[l] : -1;
    }
    if constexpr (N == 3) {  // a crown's outline, from the measurement most likely its own
      const int l = jpdaf_.likelyMeasurement(k);
      if (l >= 0) track.outline.observe(scan.observations[obs_ids_[l]].outline);
    }
    if constexpr (N == 4) {
      // Nothing of it in this scan: the camera's view says where it is not.
      if (!track.detected && track.visibility > 0.0 && config_.negative_information) {
        const double p_miss_visible = config_.p_detect * config_.gate_probability;  // P_D P_G
        track.posterior = afterMissedDetection(track.prior, p_miss_visible, [&](const Vec2& p) {
          return targetVisible(p, own_footprint, own_map, camera, scan.sensor_position,
                               scan.sensor_height);
        });
      }
    }
    if (track.detected) {
      track.expected_misses = 0;
    } else if (expectedVisible(track, own_footprint, own_map, camera, scan.sensor_position,
                               scan.sensor_height)) {
      ++track.expected_misses;
    }
  }

  // Births: one tentative track per measurement in no track's birth gate
  // (config.birth_gate_probability).
  for (int l = 0; l < static_cast<int>(obs_ids_.size()); ++l) {
    if (claimed_[l]) continue;
    Track<N> track;
    track.key = {agent_, next_serial_++};
    track.label = label;
    track.posterior = Model::birth(scan.observations[obs_ids_[l]], config_);
    track.prior = track.posterior;
    track.scans = 1;
    track.hits = 1;
    track.detected = true;
    track.existence = config_.birth_existence;
    track.existence_prior = config_.birth_existence;
    if constexpr (N == 3) track.outline.observe(scan.observations[obs_ids_[l]].outline);
    tracks.push_back(track);
    ++diagnostics_.births;
  }
}

template <int N>
void Tracker::confirmOrDrop(std::vector<Track<N>>& tracks) {
  if (config_.confirmation == TrackConfirmation::existence) {
    // JIPDA: confirmed once r ≥ confirm_existence; a tentative track whose r fell below
    // delete_existence is dropped at once (confirmed ones are judged after fusion, deleteStale).
    for (Track<N>& track : tracks) {
      if (track.status == TrackStatus::tentative && track.existence >= config_.confirm_existence)
        track.status = TrackStatus::confirmed;
    }
    const auto dropped = std::erase_if(tracks, [this](const Track<N>& track) {
      return track.status == TrackStatus::tentative && track.existence < config_.delete_existence;
    });
    diagnostics_.deletions += static_cast<long>(dropped);
    return;
  }
  for (Track<N>& track : tracks) {
    if (track.status == TrackStatus::tentative && track.hits >= config_.confirm_hits &&
        track.scans <= config_.confirm_window) {
      track.status = TrackStatus::confirmed;
    }
  }
  // Dropped once even a hit in every remaining scan of the window cannot confirm it.
  const auto dropped = std::erase_if(tracks, [this](const Track<N>& track) {
    const int remaining = std::max(0, config_.confirm_window - track.scans);
    return track.status == TrackStatus::tentative && track.hits + remaining < config_.confirm_hits;
  });
  diagnostics_.deletions += static_cast<long>(dropped);
}

void Tracker::adopt(std::vector<TargetTrack>&& targets, std::vector<TreeTrack>&& trees) {
  targets_.swap(targets);
  trees_.swap(trees);
}

void Tracker::mergeDuplicates() {
  const int merged =
      merger_.merge(targets_, config_.merge_gate, config_.merge_scans, config_.merge_distance);
  diagnostics_.merges += merged;
  diagnostics_.deletions += merged;
}

void Tracker::deleteStale() {
  deleteStale(targets_);
  deleteStale(trees_);
}

template <int N>
void Tracker::deleteStale(std::vector<Track<N>>& tracks) {
  const auto deleted = std::erase_if(tracks, [this](const Track<N>& track) {
    const Gaussian<N>& g = track.posterior;
    if (!g.x.allFinite() || !g.P.allFinite()) return true;
    if constexpr (N == 4) {
      if (isKnown(track.key)) return false;  // lost, perhaps, but never forgotten
    }
    const double trace_pos = g.P(0, 0) + g.P(1, 1);  // tr(P_pos) (m²)
    if (trace_pos > config_.delete_trace) return true;
    if (config_.confirmation == TrackConfirmation::existence &&
        track.existence < config_.delete_existence) {
      return true;
    }
    return config_.delete_misses > 0 && track.expected_misses >= config_.delete_misses;
  });
  diagnostics_.deletions += static_cast<long>(deleted);
}

}  // namespace canopy::agents::tracking
