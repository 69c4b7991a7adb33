// The NBO cost's terminal penalty (Miller et al. 2009), one candidate at a time: each track that
// no footprint holds and no crown hides at m = H, by decreasing tr(P_{j,H}[pos]), is charged to
// the UAV whose distance to it plus the distance D_i already charged to it is least.
#include <limits>

#include "agents/planning/nominal_cost.h"

namespace canopy::agents::planning {

double NominalCost::addTerminalPenalty(int lane, double J) {
  if (!terminal_ || charged_.empty()) return J;
  const int T = horizon_ * substeps_;
  auto traceFinal = [&](int j) { return trace_final_[kLanes * j + lane]; };
  // Tracks in no footprint (this lane's) and not occluded at m = H (penalty_tracks_, in the
  // order J sums them), by decreasing tr(P_{j,H}[pos]) (ties: lower index first; stable
  // insertion sort).
  int count = 0;
  for (const int j : penalty_tracks_) {
    if (in_view_final_[kLanes * j + lane] != 0) continue;
    int slot = count++;
    for (; slot > 0 && traceFinal(uncovered_[slot - 1]) < traceFinal(j); --slot) {
      uncovered_[slot] = uncovered_[slot - 1];
    }
    uncovered_[slot] = j;
  }
  // charged_ is all zero here (prepare() and the end of every call): D_i = 0 for every UAV.
  const Vec2* final_position = &final_position_[static_cast<std::size_t>(lane) * n_uavs_];
  const std::size_t n_charged = penalty_uavs_.size();
  for (int c = 0; c < count; ++c) {
    const int j = uncovered_[c];
    const Vec2& z = z_[static_cast<std::size_t>(j) * T + T - 1];
    // |p_{i,H} − z_{j,H}| of the fixed UAVs, the same for every candidate: from prepare().
    const double* fixed_distance = &terminal_distance_[j * n_charged];
    std::size_t best = 0;
    double best_total = std::numeric_limits<double>::infinity(), best_distance = 0.0;
    // The UAVs the penalty charges (team scope: every UAV, by index, the paper's loop).
    for (std::size_t k = 0; k < n_charged; ++k) {
      // |p_{i,H} − z_{j,H}|
      const double distance =
          penalty_free_[k] ? (final_position[penalty_uavs_[k]] - z).norm() : fixed_distance[k];
      if (charged_[k] + distance < best_total) {
        best = k;
        best_total = charged_[k] + distance;
        best_distance = distance;
      }
    }
    J += weight_ * best_total * traceFinal(j);  // w (D_i + |p_{i,H} − z_{j,H}|) tr(P_{j,H}[pos])
    charged_[best] += best_distance;            // D_i += |p_{i,H} − z_{j,H}|
    charged_uavs_[c] = static_cast<int>(best);
  }
  // Back to zero: only the entries this call charged (a fill is a memset call per candidate).
  for (int c = 0; c < count; ++c) charged_[charged_uavs_[c]] = 0.0;
  return J;
}

}  // namespace canopy::agents::planning
