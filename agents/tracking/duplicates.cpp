#include "agents/tracking/duplicates.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <limits>

#include "agents/tracking/known_people.h"

namespace canopy::agents::tracking {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The survivor of a merged pair: confirmed first, then the larger existence, then the smaller key.
bool survives(const TargetTrack& a, const TargetTrack& b) {
  if (a.status != b.status) return a.status == TrackStatus::confirmed;
  if (a.existence != b.existence) return a.existence > b.existence;
  return a.key < b.key;
}

}  // namespace

double trackDistance(const TargetGaussian& a, const TargetGaussian& b) {
  const Vec4 dx = a.x - b.x;  // Δx (4)
  const Mat4 S = a.P + b.P;   // P_a + P_b (4×4)
  const Eigen::LLT<Mat4> llt(S);
  if (llt.info() != Eigen::Success) return kInfinity;
  return llt.matrixL().solve(dx).squaredNorm();  // d² = Δxᵀ S⁻¹ Δx = |L⁻¹ Δx|²
}

int DuplicateMerger::merge(std::vector<TargetTrack>& tracks, double gate, int scans,
                           double distance) {
  if (scans <= 0) return 0;
  const int n = static_cast<int>(tracks.size());
  partner_.assign(n, -1);
  best_.assign(n, kInfinity);
  const double certain_trace = 2.0 * distance * distance;  // tr(P_pos) of a certain track
  auto candidate = [&](const TargetTrack& t) {
    return t.status == TrackStatus::confirmed && t.strongest_detection >= 0 &&
           t.posterior.P(0, 0) + t.posterior.P(1, 1) <= certain_trace;
  };
  for (int a = 0; a < n; ++a) {
    if (!candidate(tracks[a])) continue;
    const TargetGaussian& ga = tracks[a].posterior;
    for (int b = a + 1; b < n; ++b) {
      if (tracks[b].label != tracks[a].label || !candidate(tracks[b])) continue;
      if (tracks[b].strongest_detection != tracks[a].strongest_detection) continue;
      if (isKnown(tracks[a].key) && isKnown(tracks[b].key))
        continue;  // two people the scenario names are two people
      const TargetGaussian& gb = tracks[b].posterior;
      if ((ga.x.head<2>() - gb.x.head<2>()).squaredNorm() > distance * distance) continue;
      const double d2 = trackDistance(ga, gb);
      if (!(d2 <= gate)) continue;
      if (d2 < best_[a]) {
        best_[a] = d2;
        partner_[a] = b;
      }
      if (d2 < best_[b]) {
        best_[b] = d2;
        partner_[b] = a;
      }
    }
  }
  for (int a = 0; a < n; ++a) {
    TargetTrack& track = tracks[a];
    if (partner_[a] < 0) {
      track.merge_streak = 0;
      continue;
    }
    const TrackKey& key = tracks[partner_[a]].key;
    track.merge_streak =
        track.merge_streak > 0 && track.merge_partner == key ? track.merge_streak + 1 : 1;
    track.merge_partner = key;
  }
  removed_.assign(n, 0);
  int removed = 0;
  for (int a = 0; a < n; ++a) {
    const int b = partner_[a];
    if (removed_[a] || b < 0 || removed_[b] || tracks[a].merge_streak < scans) continue;
    const int keep = survives(tracks[a], tracks[b]) ? a : b;
    const int drop = keep == a ? b : a;
    TargetTrack& survivor = tracks[keep];
    if (tracks[drop].status == TrackStatus::confirmed) survivor.status = TrackStatus::confirmed;
    survivor.existence = std::max(survivor.existence, tracks[drop].existence);
    survivor.merge_streak = 0;
    removed_[drop] = 1;
    ++removed;
  }
  if (removed > 0) {
    int out = 0;
    for (int a = 0; a < n; ++a) {
      if (removed_[a]) continue;
      if (out != a) tracks[out] = std::move(tracks[a]);
      ++out;
    }
    tracks.resize(out);
  }
  return removed;
}

}  // namespace canopy::agents::tracking
