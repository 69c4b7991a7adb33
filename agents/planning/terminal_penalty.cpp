// The NBO cost's terminal penalty (Miller et al. 2009), one candidate at a time: each track that
// no footprint holds and no crown hides at m = H, by decreasing tr(P_{j,H}[pos]), is charged to
// the UAV whose distance to it plus the distance D_i already charged to it is least.
#include <algorithm>
#include <limits>

#include "agents/planning/nominal_cost.h"

namespace canopy::agents::planning {

double NominalCost::addTerminalPenalty(int lane, double J) {
  if (!terminal_ || charged_.empty()) return J;
  const int T = horizon_ * substeps_;
  auto traceFinal = [&](int j) { return trace_final_[kLanes * j + lane]; };
  // Tracks in no footprint and not occluded at m = H, by decreasing tr(P_{j,H}[pos]) (ties: lower
  // index first; stable insertion sort).
  int count = 0;
  auto insert = [&](int j) {
    if (in_view_final_[kLanes * j + lane] != 0 ||
        occluded_[static_cast<std::size_t>(j) * T + T - 1])
      return;
    int slot = count++;
    for (; slot > 0 && traceFinal(uncovered_[slot - 1]) < traceFinal(j); --slot) {
      uncovered_[slot] = uncovered_[slot - 1];
    }
    uncovered_[slot] = j;
  };
  if (scope_ == CostScope::team) {
    const int n_targets = static_cast<int>(start_.size());
    for (int j = 0; j < n_targets; ++j) insert(j);
  } else {
    for (const int j : scope_tracks_) insert(j);
  }
  std::fill(charged_.begin(), charged_.end(), 0.0);
  const Vec2* final_position = &final_position_[static_cast<std::size_t>(lane) * n_uavs_];
  for (int c = 0; c < count; ++c) {
    const int j = uncovered_[c];
    const Vec2& z = z_[static_cast<std::size_t>(j) * T + T - 1];
    int best = 0;
    double best_total = std::numeric_limits<double>::infinity(), best_distance = 0.0;
    // Team scope: every UAV, by index (the paper's loop); reach scope: the UAVs in penalty_uavs_.
    auto consider = [&](int k, int i) {
      const double distance = (final_position[i] - z).norm();  // |p_{i,H} − z_{j,H}|
      if (charged_[k] + distance < best_total) {
        best = k;
        best_total = charged_[k] + distance;
        best_distance = distance;
      }
    };
    if (scope_ == CostScope::team) {
      for (int i = 0; i < n_uavs_; ++i) consider(i, i);
    } else {
      const int n_charged = static_cast<int>(penalty_uavs_.size());
      for (int k = 0; k < n_charged; ++k) consider(k, penalty_uavs_[k]);
    }
    J += weight_ * best_total * traceFinal(j);  // w (D_i + |p_{i,H} − z_{j,H}|) tr(P_{j,H}[pos])
    charged_[best] += best_distance;            // D_i += |p_{i,H} − z_{j,H}|
  }
  return J;
}

}  // namespace canopy::agents::planning
