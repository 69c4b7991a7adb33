#pragma once
// The paper's behaviour detectors (§IV, algorithms.md §7) on per-step visibility histories.
// Pure functions: a history in, answers out.
#include <cstdint>
#include <string>
#include <vector>

#include "spec/scenario_spec.h"

namespace canopy::analysis {

/// A set of targets as bits: bit t set ⇔ target t is in the set (analysis supports ≤ 64 targets).
using TargetSet = std::uint64_t;
inline constexpr int kMaxAnalysedTargets = 64;
inline TargetSet bit(int t) {
  return TargetSet{1} << t;
}

/// sets[k][i]: UAV i's set at step k (visible targets V_{i,k}, footprint membership, or M_{i,k}).
using SetHistory = std::vector<std::vector<TargetSet>>;

/// m-Ownership (paper Def. 1 as algorithms.md §7 reads it): i owns t at k iff t ∈ V_{i,k+h} for
/// h = 0..m−1. Near the end, where fewer than m steps remain, the last full window
/// [K − m + 1, K] decides, so that M_K (the Sankey's last column) is defined.
SetHistory mOwnership(const SetHistory& visible, int m);

/// Ownership_Change[k, i →(t, L) j]: t ∈ M_{i,k}, t ∉ M_{j,k}, t ∈ M_{j,k+L}, t ∉ M_{i,k+L}.
struct OwnershipChange {
  int from = 0;    // i
  int to = 0;      // j
  int target = 0;  // t
  friend bool operator==(const OwnershipChange&, const OwnershipChange&) = default;
};
bool ownershipChange(const SetHistory& M, int k, int L, int i, int j, int t);
/// Every (i, j, t) with an Ownership_Change from k to k + L, ordered by (i, j, t).
std::vector<OwnershipChange> ownershipChanges(const SetHistory& M, int k, int L, int targets);

/// Occlusion_Aware(k0, t, W, L, h) (paper Def. 3), given that t is occluded at every step of
/// [k0 + h, k0 + L − h] (checked: false otherwise):
///   1. some UAV owns t at k0;
///   2. no UAV both owns nothing and holds t in its footprint at every step of [k0+h, k0+L−h];
///   3. some UAV owns t at k0 + L.
/// in_footprint[k][i]: targets whose true position lies in φ_{i,k}; occluded[k]: targets
/// strictly under a crown at k.
bool occlusionAware(const SetHistory& M, const SetHistory& in_footprint,
                    const std::vector<TargetSet>& occluded, int t, int k0, int L, int h);

/// Maximal runs [first, last] (inclusive steps) where target t is in the per-step sets.
struct Interval {
  int first = 0;
  int last = 0;
  friend bool operator==(const Interval&, const Interval&) = default;
};
std::vector<Interval> runsOf(const std::vector<TargetSet>& per_step, int t);

/// The named ownership state of M_k: the first named assignment it equals (any UAV order when the
/// state allows it), else "Miss 1" / "Miss >1" when exactly one / more than one target is owned
/// by no UAV, else "Other".
std::string ownershipState(const std::vector<TargetSet>& M_k,
                           const std::vector<spec::NamedOwnership>& named, int targets);

}  // namespace canopy::analysis
