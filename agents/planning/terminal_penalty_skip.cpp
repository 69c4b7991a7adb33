// The terminal penalty's exact skip (issue 48): a candidate charges again only the tracks whose
// charge it can change.
//
// The penalty (terminal_penalty.cpp) walks the uncovered tracks by decreasing tr(P_{j,H}[pos])
// and charges each to the UAV of least D_i + |p_{i,H} − z_{j,H}|, D_i growing by each charge.
// With one agent free among many, most tracks are ones no candidate changes (no free UAV can see
// them: penalty_fixed_order_), and most UAVs are fixed. prepare() charges those tracks once to
// the fixed UAVs alone — the baseline: entry b_c, total t_c, D_k(c) before each position c.
// A candidate's walk differs from the baseline only through the UAVs whose D_i differs from it
// ("changed": the free UAVs from the start, and every UAV that gains or loses a charge). At a
// baseline track c, the charge can differ from (b_c, t_c) only when
//   b_c is changed, or some changed k has D'_k + |p_k − z_c| ≤ t_c;
// since D'_k ≥ 0, only at positions with |p_k − z_c| ≤ t_c: each UAV's contest list, made once.
// The other baseline tracks keep their charge and the UAVs their D_i, so the walk visits only the
// contest lists of the changed UAVs and the varying tracks the candidate leaves uncovered, in the
// penalty's order. At a visited track the least (D_i + distance, entry) is taken over the changed
// UAVs (their D'_i) and the unchanged ones (D_k(c): b_c itself when it is unchanged, else a
// nearest-first search), each total the same floating-point sum as the loop's: the charges are
// the loop's. Only the penalty's sum differs in order: Σ_c w·t_c·tr_c once, plus the visited
// tracks' differences.
#include <algorithm>
#include <cmath>
#include <limits>

#include "agents/planning/interaction.h"
#include "agents/planning/nominal_cost.h"

namespace canopy::agents::planning {

double NominalCost::baselineChargedBefore(int entry, int c) const {
  double charged = 0.0;  // D_k before any charge
  for (int w = win_offset_[entry]; w < win_offset_[entry + 1] && win_position_[w] < c; ++w)
    charged = win_after_[w];
  return charged;
}

void NominalCost::prepareSkip() {
  const std::size_t n_order = penalty_fixed_order_.size();
  if (!penalty_skip_) return;  // preparePenalty decided
  const int T = horizon_ * substeps_;
  const std::size_t n_charged = penalty_uavs_.size();
  // The baseline: the loop over penalty_fixed_order_ with the fixed entries only (lane 0: these
  // tracks are the same in every lane). Its charge is the least (D_k + distance, entry) over the
  // fixed entries (every distance finite: penalty_nearest_), found here by looking at each, as
  // the nearest-first search finds it (one farther than the least total cannot reach it).
  std::vector<double> charged(n_charged, 0.0);
  std::vector<int> wins(n_charged, 0);
  base_.resize(n_order);
  base_penalty_ = 0.0;
  for (std::size_t c = 0; c < n_order; ++c) {
    const int j = penalty_fixed_order_[c];
    const double* distance = &terminal_distance_[j * n_charged];
    BaseCharge best{0, std::numeric_limits<double>::infinity(), 0.0};
    for (const int entry : penalty_fixed_entries_) {
      const double total = charged[entry] + distance[entry];
      if (total < best.total || (total == best.total && entry < best.entry))
        best = {entry, total, distance[entry]};
    }
    base_[c] = best;
    base_penalty_ += weight_ * best.total * trace_final_[kLanes * j];  // w (D_i + d) tr(P_{j,H})
    charged[best.entry] += best.distance;
    ++wins[best.entry];
  }
  // Each entry's charges, by position, with D_k after each.
  win_offset_.assign(n_charged + 1, 0);
  for (std::size_t e = 0; e < n_charged; ++e) win_offset_[e + 1] = win_offset_[e] + wins[e];
  win_position_.resize(n_order);
  win_after_.resize(n_order);
  std::vector<int> fill(win_offset_.begin(), win_offset_.end() - 1);
  std::fill(charged.begin(), charged.end(), 0.0);
  for (std::size_t c = 0; c < n_order; ++c) {
    const int e = base_[c].entry;
    charged[e] += base_[c].distance;
    win_position_[fill[e]] = static_cast<int>(c);
    win_after_[fill[e]++] = charged[e];
  }
  // Contest lists: the positions each entry could take (or, charged there, give up).
  std::vector<double> travel(n_charged, 0.0);  // m, how far a free entry's UAV can fly
  std::vector<Vec2> start(n_charged, Vec2::Zero());
  for (std::size_t f = 0; f < free_.size(); ++f) {
    for (const int e : penalty_free_entries_) {
      if (penalty_uavs_[e] != free_index_[f]) continue;
      start[e] = free_[f].position;
      travel[e] = free_[f].v_max * horizon_ * period_ + kReachSlack;  // speeds clamped to v_max
    }
  }
  auto contests = [&](int e, std::size_t c) {
    const int j = penalty_fixed_order_[c];
    if (!penalty_free_[e]) return terminal_distance_[j * n_charged + e] <= base_[c].total;
    const Vec2& z = z_[static_cast<std::size_t>(j) * T + T - 1];
    return (start[e] - z).norm() <= base_[c].total + travel[e];
  };
  contest_offset_.assign(n_charged + 1, 0);
  contest_position_.clear();
  for (std::size_t e = 0; e < n_charged; ++e) {
    for (std::size_t c = 0; c < n_order; ++c) {
      if (contests(static_cast<int>(e), c)) contest_position_.push_back(static_cast<int>(c));
    }
    contest_offset_[e + 1] = static_cast<int>(contest_position_.size());
  }
  changed_slot_.assign(n_charged, -1);
  changed_.clear();
}

double NominalCost::wholePenalty(int lane, double J) {
  // The charge of every track it may charge, each searched nearest first: every track's order.
  for (const int j : charged_tracks_)
    if (!nearest_sorted_[j]) sortNearest(j);
  return addTerminalPenaltyAtScale(lane, J);
}

double NominalCost::addTerminalPenaltySkipping(int lane, double J) {
  const int T = horizon_ * substeps_;
  auto traceFinal = [&](int j) { return trace_final_[kLanes * j + lane]; };
  // The penalty's order between two tracks (merge's rule): a before b.
  auto precedes = [&](int a, int b) {
    return traceFinal(a) > traceFinal(b) || (traceFinal(a) == traceFinal(b) && a < b);
  };
  // The varying tracks this candidate leaves uncovered, in the penalty's order.
  int* varying = uncovered_.data();
  int n_varying = 0;
  for (const int j : penalty_varying_) {
    if (in_view_final_[kLanes * j + lane] != 0) continue;
    if (!std::isfinite(traceFinal(j))) return wholePenalty(lane, J);  // its ties
    int slot = n_varying++;
    for (; slot > 0 && traceFinal(varying[slot - 1]) < traceFinal(j); --slot)
      varying[slot] = varying[slot - 1];
    varying[slot] = j;
  }

  const int n_order = static_cast<int>(base_.size());
  const std::size_t n_charged = penalty_uavs_.size();
  const std::size_t n_fixed = penalty_fixed_entries_.size();
  const Vec2* final_position = &final_position_[static_cast<std::size_t>(lane) * n_uavs_];
  for (const Changed& k : changed_) changed_slot_[k.entry] = -1;
  changed_.clear();
  // Entry e joins the changed UAVs with D_e = charged; its contest list from position `from`.
  auto change = [&](int e, double charged, int from) {
    const int* list = contest_position_.data();
    const int cursor = static_cast<int>(
        std::lower_bound(list + contest_offset_[e], list + contest_offset_[e + 1], from) - list);
    changed_slot_[e] = static_cast<int>(changed_.size());
    changed_.push_back({e, charged, cursor});
  };
  for (const int e : penalty_free_entries_) change(e, 0.0, 0);

  double penalty = base_penalty_;  // Σ_c w·t_c·tr_c, then the visited tracks' differences
  // Charges track j, at position c of the baseline's order (base: its baseline charge) or, a
  // varying track, before position c (base: nullptr).
  auto charge = [&](int j, int c, const BaseCharge* base) {
    ++penalty_charges_;
    const Vec2& z = z_[static_cast<std::size_t>(j) * T + T - 1];
    const double* fixed_distance = &terminal_distance_[j * n_charged];
    int best = 0;
    double best_total = std::numeric_limits<double>::infinity(), best_distance = 0.0;
    auto consider = [&](int e, double total, double distance) {
      if (total < best_total || (total == best_total && e < best)) {
        best = e;
        best_total = total;
        best_distance = distance;
      }
    };
    for (const Changed& k : changed_) {
      const double distance = penalty_free_[k.entry]
                                  ? (final_position[penalty_uavs_[k.entry]] - z).norm()
                                  : fixed_distance[k.entry];
      consider(k.entry, k.charged + distance, distance);
    }
    if (base != nullptr && changed_slot_[base->entry] < 0) {
      consider(base->entry, base->total, base->distance);  // the least of the unchanged ones
    } else {  // the unchanged fixed entries, nearest first, at their D_k(c)
      if (!nearest_sorted_[j]) sortNearest(j);
      const int* k = &nearest_fixed_[j * n_fixed];
      const int *sorted_end = k + nearestSorted(), *end = k + n_fixed;
      for (; k != end; ++k) {
        const double distance = fixed_distance[*k];
        if (distance > best_total) {
          if (k < sorted_end) break;  // the rest are no nearer
          continue;
        }
        if (changed_slot_[*k] >= 0) continue;
        consider(*k, baselineChargedBefore(*k, c) + distance, distance);
      }
    }
    // w (D_i + |p_{i,H} − z_{j,H}|) tr(P_{j,H}[pos]), less the baseline's term
    penalty += weight_ * best_total * traceFinal(j);
    if (base != nullptr) penalty -= weight_ * base->total * traceFinal(j);
    const int next = base != nullptr ? c + 1 : c;  // the first position still to come
    if (changed_slot_[best] >= 0) {
      changed_[changed_slot_[best]].charged += best_distance;  // D_i += |p_{i,H} − z_{j,H}|
    } else if (base == nullptr || best != base->entry) {
      change(best, baselineChargedBefore(best, c) + best_distance, next);
    }
    if (base != nullptr && best != base->entry && changed_slot_[base->entry] < 0)
      change(base->entry, baselineChargedBefore(base->entry, c), next);  // gives up its charge
  };

  int v = 0;
  for (;;) {
    if (changed_.size() > kSkipMaxChanged) return wholePenalty(lane, J);
    int next = n_order;  // the next position some changed UAV could take
    for (const Changed& k : changed_) {
      if (k.cursor < contest_offset_[k.entry + 1])
        next = std::min(next, contest_position_[k.cursor]);
    }
    if (v < n_varying && (next == n_order || !precedes(penalty_fixed_order_[next], varying[v]))) {
      const int j = varying[v++];
      const int before = static_cast<int>(
          std::partition_point(penalty_fixed_order_.begin(), penalty_fixed_order_.end(),
                               [&](int f) { return precedes(f, j); }) -
          penalty_fixed_order_.begin());
      charge(j, before, nullptr);
      continue;
    }
    if (next == n_order) break;
    charge(penalty_fixed_order_[next], next, &base_[next]);
    for (Changed& k : changed_) {
      while (k.cursor < contest_offset_[k.entry + 1] && contest_position_[k.cursor] <= next)
        ++k.cursor;
    }
  }
  return J + penalty;
}

}  // namespace canopy::agents::planning
