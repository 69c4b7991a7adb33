#pragma once
// Duplicate target tracks: two tracks on one target (a track born beside its target's track, or
// two agents' tracks that fusion did not associate) share the target's measurements, so their
// states converge. Only such pairs may merge. A pair passes the test at a scan when
//   - both are confirmed and certain: tr(P_pos) ≤ 2·merge_distance² each;
//   - their means lie within merge_distance of each other (absolute, not only relative to P);
//   - d² = Δxᵀ (P_a + P_b)⁻¹ Δx ≤ merge_gate (χ²₄): their velocities agree too;
//   - the own scan's strongest measurement of both is the same one (they were updated by one
//     detection; two people seen in one scan give two, and the pair is apart);
//   - not both are known people (pre-seeded keys): the scenario says they are two.
// After merge_scans consecutive passes the pair merges. Why each: P_a + P_b widens as tracks go
// unseen, so the Mahalanobis test alone merges two people whose tracks grew uncertain; two people
// walking together stay apart because a scan that sees both sees two detections; and two tracks
// that shared no detection of this agent's own have nothing to show they are one person.
#include <vector>

#include "agents/tracking/track.h"

namespace canopy::agents::tracking {

/// Track-to-track Mahalanobis distance of two posteriors (Bar-Shalom 1981's test without the
/// cross-covariance, which makes it looser): d² = Δxᵀ (P_a + P_b)⁻¹ Δx, Δx = x_a − x_b (4-D);
/// +∞ when P_a + P_b is not positive definite.
double trackDistance(const TargetGaussian& a, const TargetGaussian& b);

/// Keeps the buffers of the test between scans.
class DuplicateMerger {
 public:
  /// One scan of the test on `tracks` (all labels; only tracks of one label pair up). Each track's
  /// partner is the track of its label passing the test above with the smallest d²; its
  /// merge_streak counts
  /// the consecutive calls with the same partner (by key). A track whose streak reaches `scans`
  /// is merged with its partner: the survivor is the confirmed one, else the one more likely to
  /// exist, else the smaller key; it keeps its own state, becomes confirmed if either was and
  /// takes the larger existence. The other is removed (order of the rest kept). Returns the
  /// number removed. scans ≤ 0: nothing is done.
  int merge(std::vector<TargetTrack>& tracks, double gate, int scans, double distance);

 private:
  std::vector<int> partner_;   // per track: index of its partner this scan, or −1
  std::vector<double> best_;   // per track: d² to it
  std::vector<char> removed_;  // per track
};

}  // namespace canopy::agents::tracking
