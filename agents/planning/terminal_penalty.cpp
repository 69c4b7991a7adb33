// The NBO cost's terminal penalty (Miller et al. 2009), one candidate at a time: each track that
// no footprint holds and no crown hides at m = H, by decreasing tr(P_{j,H}[pos]), is charged to
// the UAV whose distance to it plus the distance D_i already charged to it is least.
#include <cmath>
#include <limits>

#include "agents/planning/nominal_cost.h"

namespace canopy::agents::planning {

// Tracks in no footprint (this lane's) and not occluded at m = H (penalty_tracks_, in the order J
// sums them), into uncovered_ by decreasing tr(P_{j,H}[pos]) (ties: lower index first; stable
// insertion sort); their count.
inline int NominalCost::sortUncovered(int lane) {
  auto traceFinal = [&](int j) { return trace_final_[kLanes * j + lane]; };
  int count = 0;
  for (const int j : penalty_tracks_) {
    if (in_view_final_[kLanes * j + lane] != 0) continue;
    int slot = count++;
    for (; slot > 0 && traceFinal(uncovered_[slot - 1]) < traceFinal(j); --slot) {
      uncovered_[slot] = uncovered_[slot - 1];
    }
    uncovered_[slot] = j;
  }
  return count;
}

// The entry of penalty_uavs_ with the least D_i + |p_{i,H} − z_{j,H}|, every entry by index (the
// first least one wins): the free UAVs' distances from this lane's final positions, the fixed
// ones' from prepare().
inline NominalCost::Charge NominalCost::leastChargeByIndex(const Vec2* final_position,
                                                           const Vec2& z,
                                                           const double* fixed_distance) const {
  Charge least{0, std::numeric_limits<double>::infinity(), 0.0};
  for (std::size_t k = 0; k < penalty_uavs_.size(); ++k) {
    // |p_{i,H} − z_{j,H}|
    const double distance =
        penalty_free_[k] ? (final_position[penalty_uavs_[k]] - z).norm() : fixed_distance[k];
    if (charged_[k] + distance < least.total) least = {k, charged_[k] + distance, distance};
  }
  return least;
}

double NominalCost::addTerminalPenalty(int lane, double J) {
  if (!terminal_ || charged_.empty()) return J;
  // Many tracks or UAVs: the same bits by a merge and a nearest-first search, or, with many
  // tracks no candidate changes, only those it can (terminal_penalty_skip.cpp).
  if (penalty_merge_ || penalty_nearest_) {
    return penalty_skip_ ? addTerminalPenaltySkipping(lane, J)
                         : addTerminalPenaltyAtScale(lane, J);
  }
  const int T = horizon_ * substeps_;
  auto traceFinal = [&](int j) { return trace_final_[kLanes * j + lane]; };
  // Tracks in no footprint (this lane's) and not occluded at m = H (penalty_tracks_, in the
  // order J sums them), by decreasing tr(P_{j,H}[pos]) (ties: lower index first; stable
  // insertion sort).
  const int count = sortUncovered(lane);
  // charged_ is all zero here (prepare() and the end of every call): D_i = 0 for every UAV.
  const Vec2* final_position = &final_position_[static_cast<std::size_t>(lane) * n_uavs_];
  const std::size_t n_charged = penalty_uavs_.size();
  for (int c = 0; c < count; ++c) {
    const int j = uncovered_[c];
    const Vec2& z = z_[static_cast<std::size_t>(j) * T + T - 1];
    // |p_{i,H} − z_{j,H}| of the fixed UAVs, the same for every candidate: from prepare().
    const double* fixed_distance = &terminal_distance_[j * n_charged];
    // The UAVs the penalty charges (team scope: every UAV, by index, the paper's loop).
    const Charge least = leastChargeByIndex(final_position, z, fixed_distance);
    const std::size_t best = least.entry;
    const double best_total = least.total, best_distance = least.distance;
    J += weight_ * best_total * traceFinal(j);  // w (D_i + |p_{i,H} − z_{j,H}|) tr(P_{j,H}[pos])
    charged_[best] += best_distance;            // D_i += |p_{i,H} − z_{j,H}|
    charged_uavs_[c] = static_cast<int>(best);
  }
  // Back to zero: only the entries this call charged (a fill is a memset call per candidate).
  for (int c = 0; c < count; ++c) charged_[charged_uavs_[c]] = 0.0;
  return J;
}

double NominalCost::addTerminalPenaltyAtScale(int lane, double J) {
  const int T = horizon_ * substeps_;
  auto traceFinal = [&](int j) { return trace_final_[kLanes * j + lane]; };
  // Tracks in no footprint (this lane's) and not occluded at m = H (penalty_tracks_, in the
  // order J sums them), by decreasing tr(P_{j,H}[pos]) (ties: lower index first; stable
  // insertion sort).
  int count = 0;
  bool merged = penalty_merge_;
  if (merged) {
    // The same order by a merge: the tracks a candidate changes, sorted here by insertion (they
    // are few), and the rest, sorted once by prepare(); ties go to the lower index, as below.
    int* varying = charged_uavs_.data();  // scratch until the charging below fills it
    int n_varying = 0;
    for (const int j : penalty_varying_) {
      if (in_view_final_[kLanes * j + lane] != 0) continue;
      merged = merged && std::isfinite(traceFinal(j));
      int slot = n_varying++;
      for (; slot > 0 && traceFinal(varying[slot - 1]) < traceFinal(j); --slot)
        varying[slot] = varying[slot - 1];
      varying[slot] = j;
    }
    if (merged) {
      std::size_t f = 0;
      int v = 0;
      while (f < penalty_fixed_order_.size() || v < n_varying) {
        const bool take_fixed =
            v == n_varying || (f < penalty_fixed_order_.size() &&
                               (traceFinal(penalty_fixed_order_[f]) > traceFinal(varying[v]) ||
                                (traceFinal(penalty_fixed_order_[f]) == traceFinal(varying[v]) &&
                                 penalty_fixed_order_[f] < varying[v])));
        uncovered_[count++] = take_fixed ? penalty_fixed_order_[f++] : varying[v++];
      }
    }
  }
  if (!merged) count = sortUncovered(lane);
  penalty_charges_ += static_cast<std::size_t>(count);
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
    // The UAVs the penalty charges (team scope: every UAV, the paper's loop): the least
    // D_i + |p_{i,H} − z_{j,H}|, the lowest entry among equals.
    auto consider = [&](std::size_t k, double distance) {
      const double total = charged_[k] + distance;
      if (total < best_total || (total == best_total && k < best)) {
        best = k;
        best_total = total;
        best_distance = distance;
      }
    };
    if (penalty_nearest_) {
      for (const int k : penalty_free_entries_)
        consider(k, (final_position[penalty_uavs_[k]] - z).norm());
      // The fixed ones nearest first: one farther than best_total cannot reach it (D_i ≥ 0).
      // consider() keeps the least (total, entry) whatever the order, so the unsorted rest, each
      // no nearer than the last sorted one, is looked at in any order and the bits stay the same.
      const std::size_t n_fixed = penalty_fixed_entries_.size();
      const int* k = &nearest_fixed_[j * n_fixed];
      const int *sorted_end = k + nearestSorted(), *end = k + n_fixed;
      bool stopped = false;
      for (; k != sorted_end && !stopped; ++k) {
        stopped = fixed_distance[*k] > best_total;
        if (!stopped) consider(*k, fixed_distance[*k]);
      }
      for (; k != end && !stopped; ++k) {
        if (fixed_distance[*k] <= best_total) consider(*k, fixed_distance[*k]);
      }
    } else {  // by entry: the first least one wins
      const Charge least = leastChargeByIndex(final_position, z, fixed_distance);
      best = least.entry;
      best_total = least.total;
      best_distance = least.distance;
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
