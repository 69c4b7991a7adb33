#pragma once
// Track value types (Stone Soup's vocabulary): a track is a labelled Gaussian with a global key
// and a little bookkeeping for confirmation and deletion. Targets use the NCV state
// (px, py, vx, vy); trees the static state (cx, cy, r).
#include <type_traits>

#include "agents/belief.h"
#include "agents/gaussian.h"
#include "agents/tracking/tree_outline.h"
#include "sensing/observation.h"

namespace canopy::agents::tracking {

enum class TrackStatus { tentative, confirmed };

/// The origin of the keys of pre-seeded tracks: the people the scenario says exist.
inline constexpr int kKnownOrigin = -1;

template <int N>
struct Track {
  TrackKey key;  // global key; {-1, t} for tracks pre-seeded from the scenario
  sensing::LabelId label = 1;
  Gaussian<N> prior;      // this step's prediction, before the local update
  Gaussian<N> posterior;  // after the local update; fusion overwrites it in place
  TrackStatus status = TrackStatus::tentative;
  int scans = 0;            // scans since birth (the birth scan counts)
  int hits = 0;             // scans in which Σ_j β_tj ≥ ½ (see Tracker::update)
  int expected_misses = 0;  // consecutive misses while expected visible
  bool detected = false;    // this scan: at least one measurement in the gate
  // JIPDA (agents/tracking/existence.h): probability of existence after this step's update (and
  // fusion), and its prediction ψ = p_S · r before the update.
  double existence = 1.0;
  double existence_prior = 1.0;
  double visibility = 1.0;  // this scan: P(visible) of the predicted position to the own camera
  // Duplicate test (Tracker::mergeDuplicates): the track that passed the test last scan and for
  // how many consecutive scans it has; and this scan's measurement (index into the own scan's
  // observations) with the largest association probability, −1 for none or for a copy adopted
  // from a neighbour (its measurements are not the own scan's).
  TrackKey merge_partner;
  int merge_streak = 0;
  int strongest_detection = -1;
  // Trees only: the outline of a polygonal crown or wall, when one was measured.
  [[no_unique_address]] std::conditional_t<N == 3, TreeOutline, NoOutline> outline;
};

using TargetTrack = Track<4>;
using TreeTrack = Track<3>;

/// Numerical trouble and approximations, counted rather than aborting (MuJoCo's habit).
struct TrackingDiagnostics {
  long approximated_clusters = 0;     // clusters with more joint events than max_hypotheses
  long non_positive_covariances = 0;  // updates that needed repair to stay positive definite
  long births = 0;
  long deletions = 0;
  long merges = 0;  // duplicate tracks merged into another (counted in deletions too)
};

}  // namespace canopy::agents::tracking
