#pragma once
// An occlusion map for planning: a set of tree crowns with a uniform-grid index, so that
// "is this point under a crown?" costs O(1) however many trees there are. Built from the true
// trees (a-priori map) or from an agent's fused tree tracks (dynamic map Ŵ_i).
#include <algorithm>
#include <vector>

#include "agents/belief.h"
#include "core/types.h"
#include "world/tree.h"

namespace canopy::agents {

class OcclusionMap {
 public:
  OcclusionMap() = default;
  explicit OcclusionMap(std::vector<world::TreeDef> trees);
  /// Crowns at the estimated centres: the estimated outline's polygon when one was measured (and
  /// is convex), else a disc of the estimated radius (never below min_radius).
  static OcclusionMap fromEstimates(const std::vector<TreeEstimate>& trees, double min_radius);

  /// True when p is strictly inside some crown of the map.
  bool occludes(const Vec2& p) const;
  /// True when the segment from a to b enters some crown of the map before b (a inside one
  /// counts): the line-of-sight test of sensing (World::firstOccluderOnSegment, the same exact
  /// world::segmentEntry), here against the map's trees. A segment shorter than 10⁻⁶ m is the
  /// point test at a, as there.
  bool blocksSegment(const Vec2& a, const Vec2& b) const;
  /// The 3-D test of sensing's `volumes` model (World::sightBlocked, the same exact
  /// world::blocksSight) against the map's crown volumes: true when the segment from (a, ha) to
  /// (b, hb), heights in m above the ground, passes through some crown's prism. An estimated crown
  /// (fromEstimates) has no measured height: it fills the ground to above any UAV.
  bool blocksSight(const Vec2& a, double ha, const Vec2& b, double hb) const;
  /// True when a head at height `head` (m) above p lies strictly inside some crown's volume
  /// (p strictly inside the outline, base < head < top): hidden from every camera. With crowns
  /// from the ground up (the defaults) the same as occludes(p).
  bool hidesHead(const Vec2& p, double head) const;
  const std::vector<world::TreeDef>& trees() const { return trees_; }
  bool empty() const { return trees_.empty(); }

 private:
  /// Whether `hits` holds for some tree listed in a grid cell of the box of a and b (every tree
  /// whose box meets that box is listed in one of them).
  template <class Hit>
  bool anyTreeNear(const Vec2& a, const Vec2& b, Hit&& hits) const {
    if (trees_.empty()) return false;
    const Vec2 lo = a.cwiseMin(b), hi = a.cwiseMax(b);
    if ((lo.array() > bounds_.hi.array()).any() || (hi.array() < bounds_.lo.array()).any()) {
      return false;  // the segment's box misses every crown's
    }
    auto index = [this](double v, double origin, int count) {  // clamped before the cast: a far
      return static_cast<int>(std::clamp((v - origin) / cell_, 0.0, count - 1.0));  // end fits
    };
    const int c0 = index(lo.x(), bounds_.lo.x(), cols_), c1 = index(hi.x(), bounds_.lo.x(), cols_);
    const int r0 = index(lo.y(), bounds_.lo.y(), rows_), r1 = index(hi.y(), bounds_.lo.y(), rows_);
    for (int r = r0; r <= r1; ++r) {
      for (int c = c0; c <= c1; ++c) {
        const int cell = r * cols_ + c;
        for (int i = cell_start_[cell]; i < cell_start_[cell + 1]; ++i) {
          if (hits(trees_[cell_trees_[i]])) return true;
        }
      }
    }
    return false;
  }

  std::vector<world::TreeDef> trees_;
  Aabb bounds_;
  double cell_ = 1.0;  // m, grid cell size
  int cols_ = 0, rows_ = 0;
  std::vector<int> cell_start_;  // CSR: trees of cell c are cell_trees_[start[c], start[c+1])
  std::vector<int> cell_trees_;
};

}  // namespace canopy::agents
