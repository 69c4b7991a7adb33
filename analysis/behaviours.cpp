#include "analysis/behaviours.h"

#include <algorithm>
#include <bit>

namespace canopy::analysis {

SetHistory mOwnership(const SetHistory& visible, int m) {
  const int steps = static_cast<int>(visible.size());
  SetHistory M(visible.size());
  for (int k = 0; k < steps; ++k) {
    const int start = std::max(0, std::min(k, steps - m));  // last full window near the end
    const int end = std::min(steps, start + m);
    const std::size_t uavs = visible[k].size();
    M[k].assign(uavs, ~TargetSet{0});
    for (int s = start; s < end; ++s) {
      for (std::size_t i = 0; i < uavs; ++i) M[k][i] &= visible[s][i];  // t ∈ V_{i,s} ∀ s
    }
  }
  return M;
}

bool ownershipChange(const SetHistory& M, int k, int L, int i, int j, int t) {
  if (k < 0 || k + L >= static_cast<int>(M.size()) || i == j) return false;
  const TargetSet b = bit(t);
  return (M[k][i] & b) && !(M[k][j] & b) && (M[k + L][j] & b) && !(M[k + L][i] & b);
}

std::vector<OwnershipChange> ownershipChanges(const SetHistory& M, int k, int L, int targets) {
  std::vector<OwnershipChange> changes;
  if (M.empty()) return changes;
  const int uavs = static_cast<int>(M.front().size());
  for (int i = 0; i < uavs; ++i) {
    for (int j = 0; j < uavs; ++j) {
      for (int t = 0; t < targets; ++t) {
        if (ownershipChange(M, k, L, i, j, t)) changes.push_back({i, j, t});
      }
    }
  }
  return changes;
}

bool occlusionAware(const SetHistory& M, const SetHistory& in_footprint,
                    const std::vector<TargetSet>& occluded, int t, int k0, int L, int h) {
  const int first = k0 + h, last = k0 + L - h;
  if (k0 < 0 || k0 + L >= static_cast<int>(M.size()) || first > last) return false;
  const TargetSet b = bit(t);
  for (int k = first; k <= last; ++k) {
    if (!(occluded[k] & b)) return false;  // the definition presumes t occluded throughout
  }
  const std::size_t uavs = M[k0].size();
  auto ownedBySome = [&](int k) {
    return std::any_of(M[k].begin(), M[k].end(), [b](TargetSet s) { return (s & b) != 0; });
  };
  if (!ownedBySome(k0)) return false;       // condition 1
  for (std::size_t i = 0; i < uavs; ++i) {  // condition 2: nobody waits idle over t
    bool waits_throughout = true;
    for (int k = first; k <= last && waits_throughout; ++k) {
      waits_throughout = M[k][i] == 0 && (in_footprint[k][i] & b);
    }
    if (waits_throughout) return false;
  }
  return ownedBySome(k0 + L);  // condition 3
}

std::vector<Interval> runsOf(const std::vector<TargetSet>& per_step, int t) {
  std::vector<Interval> runs;
  const TargetSet b = bit(t);
  for (int k = 0; k < static_cast<int>(per_step.size()); ++k) {
    if (!(per_step[k] & b)) continue;
    if (!runs.empty() && runs.back().last == k - 1) {
      runs.back().last = k;
    } else {
      runs.push_back({k, k});
    }
  }
  return runs;
}

namespace {

TargetSet setOf(const std::vector<int>& targets) {
  TargetSet s = 0;
  for (const int t : targets) s |= bit(t);
  return s;
}

bool matches(const std::vector<TargetSet>& M_k, const spec::NamedOwnership& state) {
  std::vector<TargetSet> wanted;
  for (const auto& set : state.sets) wanted.push_back(setOf(set));
  if (wanted.size() != M_k.size()) return false;
  if (!state.any_permutation) return wanted == M_k;
  std::vector<TargetSet> a = wanted, b = M_k;  // equal as multisets ⇔ some UAV order matches
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  return a == b;
}

}  // namespace

std::string ownershipState(const std::vector<TargetSet>& M_k,
                           const std::vector<spec::NamedOwnership>& named, int targets) {
  for (const spec::NamedOwnership& state : named) {
    if (matches(M_k, state)) return state.name;
  }
  TargetSet owned = 0;
  for (const TargetSet s : M_k) owned |= s;
  const TargetSet all = targets >= kMaxAnalysedTargets ? ~TargetSet{0} : bit(targets) - 1;
  const int missed = std::popcount(all & ~owned);
  if (missed == 1) return "Miss 1";
  if (missed > 1) return "Miss >1";
  return "Other";
}

}  // namespace canopy::analysis
