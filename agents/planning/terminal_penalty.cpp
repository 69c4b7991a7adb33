// The NBO cost's terminal penalty (Miller et al. 2009), one candidate at a time: each track that
// no footprint holds and no crown hides at m = H, by decreasing tr(P_{j,H}[pos]), is charged to
// the UAV whose distance to it plus the distance D_i already charged to it is least.
#include <cmath>
#include <limits>

#include "agents/planning/nominal_cost.h"

namespace canopy::agents::planning {

double NominalCost::addTerminalPenalty(int lane, double J) {
  if (!terminal_ || charged_.empty()) return J;
  if (penalty_replay_) return addTerminalPenaltyByReplay(lane, J);
  // Many tracks or UAVs: the same bits by a merge and a nearest-first search.
  if (penalty_merge_ || penalty_nearest_) return addTerminalPenaltyAtScale(lane, J);
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
  if (!merged) {
    for (const int j : penalty_tracks_) {
      if (in_view_final_[kLanes * j + lane] != 0) continue;
      int slot = count++;
      for (; slot > 0 && traceFinal(uncovered_[slot - 1]) < traceFinal(j); --slot) {
        uncovered_[slot] = uncovered_[slot - 1];
      }
      uncovered_[slot] = j;
    }
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
      const std::size_t n_fixed = penalty_fixed_entries_.size();
      for (const int *k = &nearest_fixed_[j * n_fixed], *end = k + n_fixed; k != end; ++k) {
        if (fixed_distance[*k] > best_total) break;
        consider(*k, fixed_distance[*k]);
      }
    } else {
      for (std::size_t k = 0; k < n_charged; ++k) {  // by entry: the first least one wins
        // |p_{i,H} − z_{j,H}|
        const double distance =
            penalty_free_[k] ? (final_position[penalty_uavs_[k]] - z).norm() : fixed_distance[k];
        if (charged_[k] + distance < best_total) {
          best = k;
          best_total = charged_[k] + distance;
          best_distance = distance;
        }
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

// The replay: the tracks no candidate changes (penalty_fixed_order_) charged in their order with
// each free UAV at its start, as addTerminalPenaltyAtScale() would charge them for that plan. A
// candidate's charges differ from the replay's only where a free UAV (wherever the candidate
// takes it), or a fixed one whose D_i the candidate has changed, bids otherwise; elsewhere the
// winner, its D_i + distance and so every bit of the term are the replay's.
void NominalCost::prepareReplay(std::span<const UavState> uavs) {
  const int T = horizon_ * substeps_;
  const std::size_t n_charged = penalty_uavs_.size();
  const std::size_t n_fixed = penalty_fixed_entries_.size();
  penalty_replay_ = penalty_merge_ && penalty_nearest_;
  replay_charged_.assign(n_charged, 0.0);
  dirty_.assign(penalty_free_.begin(), penalty_free_.end());  // a free entry is never the replay's
  dirty_entries_.clear();
  dirty_entries_.reserve(n_charged);  // no allocation while candidates are evaluated
  varying_order_.assign(penalty_varying_.size(), 0);
  if (!penalty_replay_) return;
  const std::size_t n = penalty_fixed_order_.size();
  replay_entry_.resize(n);
  replay_total_.resize(n);
  replay_distance_.resize(n);
  replay_free_won_.resize(n);
  std::vector<double> free_charged(n_charged, 0.0);  // the free entries' D_i in the replay
  for (std::size_t c = 0; c < n; ++c) {
    const int j = penalty_fixed_order_[c];
    const Vec2& z = z_[static_cast<std::size_t>(j) * T + T - 1];
    const double* distance = &terminal_distance_[j * n_charged];
    int best = -1;
    double best_total = std::numeric_limits<double>::infinity();
    // The least D_i + |p_{i,H} − z_{j,H}| over the fixed entries, nearest first (D_i ≥ 0), the
    // lowest entry among equals.
    for (const int *k = &nearest_fixed_[j * n_fixed], *end = k + n_fixed; k != end; ++k) {
      if (distance[*k] > best_total) break;
      const double total = replay_charged_[*k] + distance[*k];
      if (total < best_total || (total == best_total && *k < best)) {
        best = *k;
        best_total = total;
      }
    }
    replay_entry_[c] = best;
    replay_total_[c] = best_total;
    replay_distance_[c] = distance[best];
    // The free entries' bids from their starts, by the same rule.
    int winner = best;
    double winner_total = best_total, winner_distance = distance[best];
    for (const int k : penalty_free_entries_) {
      const double d = (uavs[penalty_uavs_[k]].position - z).norm();
      const double total = free_charged[k] + d;
      if (total < winner_total || (total == winner_total && k < winner)) {
        winner = k;
        winner_total = total;
        winner_distance = d;
      }
    }
    replay_free_won_[c] = winner != best;
    (winner != best ? free_charged : replay_charged_)[winner] += winner_distance;
  }
  std::fill(replay_charged_.begin(), replay_charged_.end(), 0.0);
}
double NominalCost::addTerminalPenaltyByReplay(int lane, double J) {
  const int T = horizon_ * substeps_;
  auto traceFinal = [&](int j) { return trace_final_[kLanes * j + lane]; };
  // The tracks a candidate changes, uncovered in this lane, by decreasing tr(P_{j,H}[pos]) (ties:
  // lower index first; stable insertion sort), merged below with the replay's order.
  int n_varying = 0;
  for (const int j : penalty_varying_) {
    if (in_view_final_[kLanes * j + lane] != 0) continue;
    if (!std::isfinite(traceFinal(j))) return addTerminalPenaltyAtScale(lane, J);  // its order
    int slot = n_varying++;
    for (; slot > 0 && traceFinal(varying_order_[slot - 1]) < traceFinal(j); --slot)
      varying_order_[slot] = varying_order_[slot - 1];
    varying_order_[slot] = j;
  }
  const Vec2* final_position = &final_position_[static_cast<std::size_t>(lane) * n_uavs_];
  const std::size_t n_charged = penalty_uavs_.size();
  const std::size_t n_fixed = penalty_fixed_entries_.size();
  // D_i of entry k now: the candidate's own where it differs from the replay's (charged_).
  auto charge_of = [&](int k) { return dirty_[k] ? charged_[k] : replay_charged_[k]; };
  int best = -1;
  double best_total = 0.0, best_distance = 0.0;
  auto consider = [&](int k, double distance) {
    const double total = charge_of(k) + distance;
    if (total < best_total || (total == best_total && k < best)) {
      best = k;
      best_total = total;
      best_distance = distance;
    }
  };
  // Every free entry and every dirty fixed one.
  auto considerChanged = [&](int j, const Vec2& z) {
    for (const int k : penalty_free_entries_)
      consider(k, (final_position[penalty_uavs_[k]] - z).norm());
    for (const int k : dirty_entries_) consider(k, terminal_distance_[j * n_charged + k]);
  };
  // addTerminalPenaltyAtScale()'s search: free entries, then the fixed ones nearest first.
  auto search = [&](int j, const Vec2& z) {
    best = -1;
    best_total = std::numeric_limits<double>::infinity();
    for (const int k : penalty_free_entries_)
      consider(k, (final_position[penalty_uavs_[k]] - z).norm());
    const double* fixed_distance = &terminal_distance_[j * n_charged];
    for (const int *k = &nearest_fixed_[j * n_fixed], *end = k + n_fixed; k != end; ++k) {
      if (fixed_distance[*k] > best_total) break;
      consider(*k, fixed_distance[*k]);
    }
  };
  auto markDirty = [&](int k) {  // from now on its D_i is the candidate's own
    charged_[k] = replay_charged_[k];
    dirty_[k] = 1;
    dirty_entries_.push_back(k);
  };
  std::size_t f = 0;
  int v = 0;
  while (f < penalty_fixed_order_.size() || v < n_varying) {
    const bool take_fixed =
        v == n_varying || (f < penalty_fixed_order_.size() &&
                           (traceFinal(penalty_fixed_order_[f]) > traceFinal(varying_order_[v]) ||
                            (traceFinal(penalty_fixed_order_[f]) == traceFinal(varying_order_[v]) &&
                             penalty_fixed_order_[f] < varying_order_[v])));
    const int j = take_fixed ? penalty_fixed_order_[f] : varying_order_[v];
    const Vec2& z = z_[static_cast<std::size_t>(j) * T + T - 1];
    bool as_replayed = false;  // charged to the fixed entry the replay charged, whose D_i it is
    if (take_fixed) {
      const std::size_t c = f++;
      const int fixed_best = replay_entry_[c];
      const bool clean = dirty_[fixed_best] == 0;
      if (clean) {
        // The replay's least fixed bid is the least of the entries whose D_i is the replay's.
        best = fixed_best;
        best_total = replay_total_[c];
        best_distance = replay_distance_[c];
        considerChanged(j, z);
      } else {
        search(j, z);
      }
      if (replay_free_won_[c] == 0) {
        as_replayed = clean && best == fixed_best;
        if (clean && !as_replayed) markDirty(fixed_best);   // it misses the replay's charge
        replay_charged_[fixed_best] += replay_distance_[c];  // the replay moves on
      }
    } else {
      ++v;
      search(j, z);
    }
    J += weight_ * best_total * traceFinal(j);  // w (D_i + |p_{i,H} − z_{j,H}|) tr(P_{j,H}[pos])
    if (!as_replayed) {
      if (dirty_[best] == 0) markDirty(best);
      charged_[best] += best_distance;  // D_i += |p_{i,H} − z_{j,H}|
    }
  }
  // Back to the replay's start: D_i = 0, only the free entries dirty.
  for (const int k : dirty_entries_) {
    dirty_[k] = 0;
    charged_[k] = 0.0;
  }
  dirty_entries_.clear();
  for (const int k : penalty_free_entries_) charged_[k] = 0.0;
  std::fill(replay_charged_.begin(), replay_charged_.end(), 0.0);
  return J;
}

}  // namespace canopy::agents::planning
