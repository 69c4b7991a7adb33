// The NBO cost's terminal penalty (Miller et al. 2009), one candidate at a time: each track that
// no footprint holds and no crown hides at m = H, by decreasing tr(P_{j,H}[pos]), is charged to
// the UAV whose distance to it plus the distance D_i already charged to it is least; and
// prepare()'s part for it (preparePenalty).
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "agents/planning/nominal_cost.h"

namespace canopy::agents::planning {
namespace {

// From this many tracks (or fixed UAVs) on, the terminal penalty orders them by a merge (or
// searches them nearest first): same bits, fewer instructions (preparePenalty).
constexpr std::size_t kFastPenaltyFrom = 8;

}  // namespace

bool NominalCost::distancesFinite() const {
  // |a − b| of coordinates within ±1e150 is finite: (2e150)² · 2 < 1.8e308.
  auto bounded = [](const Vec2& p) { return p.allFinite() && p.cwiseAbs().maxCoeff() <= 1e150; };
  const int T = horizon_ * substeps_;
  for (const int j : penalty_tracks_)
    if (!bounded(z_[static_cast<std::size_t>(j) * T + T - 1])) return false;
  for (const int k : penalty_fixed_entries_)
    if (!bounded(final_position_[penalty_uavs_[k]])) return false;
  return true;
}

void NominalCost::sortNearest(int j) {
  // The fixed entries by distance (then entry), the first nearestSorted() of them, so that the
  // penalty's search for the least D_i + distance stops at the first fixed UAV farther than the
  // best so far (D_i ≥ 0); a search that passes them all looks at the rest in any order.
  const double* distance = &terminal_distance_[j * penalty_uavs_.size()];
  const std::size_t n_fixed = penalty_fixed_entries_.size();
  int* order = &nearest_fixed_[j * n_fixed];
  std::copy(penalty_fixed_entries_.begin(), penalty_fixed_entries_.end(), order);
  std::partial_sort(order, order + nearestSorted(), order + n_fixed, [&](int a, int b) {
    return distance[a] < distance[b] || (distance[a] == distance[b] && a < b);
  });
  nearest_sorted_[j] = 1;
}

void NominalCost::preparePenalty(const std::vector<char>& is_free) {
  const int T = horizon_ * substeps_;
  penalty_tracks_.clear();
  for (const int j : scope_tracks_)
    if (!occluded_[static_cast<std::size_t>(j) * T + T - 1]) penalty_tracks_.push_back(j);
  // The penalty's order, by decreasing tr(P_{j,H}[pos]) and then index: the tracks no free UAV
  // can see (start_ = T) have the same trace and view in every lane, so they are sorted here once
  // and merged with the few that a candidate changes (addTerminalPenalty). A non-finite trace
  // leaves the order to the insertion sort of every call (its exact ties and NaN handling).
  penalty_fixed_order_.clear();
  penalty_varying_.clear();
  penalty_merge_ = true;
  for (const int j : penalty_tracks_) {
    if (start_[j] < T) {
      penalty_varying_.push_back(j);
      continue;
    }
    if (in_view_final_[kLanes * j] != 0) continue;  // a fixed UAV holds it at m = H
    penalty_merge_ = penalty_merge_ && std::isfinite(trace_final_[kLanes * j]);
    penalty_fixed_order_.push_back(j);
  }
  std::stable_sort(penalty_fixed_order_.begin(), penalty_fixed_order_.end(), [&](int a, int b) {
    return trace_final_[kLanes * a] > trace_final_[kLanes * b];
  });
  // Both ways give the same bits; the merge pays only past a few tracks (a paper scenario's four
  // are sorted faster by insertion).
  penalty_merge_ = penalty_merge_ && penalty_fixed_order_.size() >= kFastPenaltyFrom;
  const std::size_t n_charged = penalty_uavs_.size();
  penalty_free_.resize(n_charged);
  for (std::size_t k = 0; k < n_charged; ++k) penalty_free_[k] = is_free[penalty_uavs_[k]];
  // Entries of penalty_uavs_ that are free, and fixed.
  penalty_free_entries_.clear();
  penalty_fixed_entries_.clear();
  for (std::size_t k = 0; k < n_charged; ++k)
    (penalty_free_[k] ? penalty_free_entries_ : penalty_fixed_entries_)
        .push_back(static_cast<int>(k));
  // The tracks a candidate may charge: penalty_varying_ and penalty_fixed_order_ (a track a fixed
  // UAV holds at m = H is held in every lane, and never charged). Only theirs are needed below;
  // the others' distances decide penalty_nearest_ alone, and only when one may be non-finite.
  // A few fixed UAVs (no nearest-first search): every track's, as cheap as choosing.
  const std::size_t n_fixed = penalty_fixed_entries_.size();
  const int* rows = penalty_tracks_.data();
  std::size_t n_rows = penalty_tracks_.size();
  if (n_fixed >= kFastPenaltyFrom) {
    if (distancesFinite()) {
      charged_tracks_.assign(penalty_varying_.begin(), penalty_varying_.end());
      charged_tracks_.insert(charged_tracks_.end(), penalty_fixed_order_.begin(),
                             penalty_fixed_order_.end());
    } else {
      charged_tracks_ = penalty_tracks_;
    }
    rows = charged_tracks_.data();
    n_rows = charged_tracks_.size();
  }
  // A fixed UAV's p_{i,H} is every lane's: its distance to each z_{j,H} once, here.
  terminal_distance_.resize(start_.size() * n_charged);
  for (std::size_t r = 0; r < n_rows; ++r) {
    const int j = rows[r];
    const Vec2& z = z_[static_cast<std::size_t>(j) * T + T - 1];
    for (const int k : penalty_fixed_entries_)
      terminal_distance_[j * n_charged + k] = (final_position_[penalty_uavs_[k]] - z).norm();
  }
  nearest_fixed_.resize(start_.size() * n_fixed);
  penalty_nearest_ = n_fixed >= kFastPenaltyFrom;  // a few UAVs: the plain loop is faster
  for (std::size_t r = 0; r < n_rows && penalty_nearest_; ++r) {
    const double* distance = &terminal_distance_[rows[r] * n_charged];
    for (const int k : penalty_fixed_entries_)
      penalty_nearest_ = penalty_nearest_ && std::isfinite(distance[k]);
  }
  // Per track, its nearest fixed entries (sortNearest): now for every track the penalty may
  // charge, or, with the exact skip, at a track's first search (most tracks are never searched).
  penalty_skip_ = terminal_ && penalty_merge_ && penalty_nearest_ &&
                  penalty_fixed_order_.size() >= kSkipFrom;
  if (penalty_nearest_) {
    nearest_sorted_.assign(start_.size(), 0);
    if (!penalty_skip_)
      for (std::size_t r = 0; r < n_rows; ++r) sortNearest(rows[r]);
  }
  prepareSkip();
}


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
