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
  for (const int j : scope_tracks_) {
    if (in_view_final_[kLanes * j + lane] != 0 ||
        occluded_[static_cast<std::size_t>(j) * T + T - 1])
      continue;
    int slot = count++;
    for (; slot > 0 && traceFinal(uncovered_[slot - 1]) < traceFinal(j); --slot) {
      uncovered_[slot] = uncovered_[slot - 1];
    }
    uncovered_[slot] = j;
  }
  std::fill(charged_.begin(), charged_.end(), 0.0);
  const Vec2* final_position = &final_position_[static_cast<std::size_t>(lane) * n_uavs_];
  for (int c = 0; c < count; ++c) {
    const int j = uncovered_[c];
    const Vec2& z = z_[static_cast<std::size_t>(j) * T + T - 1];
    int best = 0;
    double best_total = std::numeric_limits<double>::infinity(), best_distance = 0.0;
    const int n_charged = static_cast<int>(penalty_uavs_.size());
    for (int k = 0; k < n_charged; ++k) {
      const double distance = (final_position[penalty_uavs_[k]] - z).norm();  // |p_{i,H} − z_{j,H}|
      if (charged_[k] + distance < best_total) {
        best = k;
        best_total = charged_[k] + distance;
        best_distance = distance;
      }
    }
    J += weight_ * best_total * traceFinal(j);  // w (D_i + |p_{i,H} − z_{j,H}|) tr(P_{j,H}[pos])
    charged_[best] += best_distance;            // D_i += |p_{i,H} − z_{j,H}|
  }
  return J;
}

}  // namespace canopy::agents::planning
