#pragma once
// An occlusion map for planning: a set of tree crowns with a uniform-grid index, so that
// "is this point under a crown?" costs O(1) however many trees there are. Built from the true
// trees (a-priori map) or from an agent's fused tree tracks (dynamic map Ŵ_i).
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
  const std::vector<world::TreeDef>& trees() const { return trees_; }
  bool empty() const { return trees_.empty(); }

 private:
  std::vector<world::TreeDef> trees_;
  Aabb bounds_;
  double cell_ = 1.0;  // m, grid cell size
  int cols_ = 0, rows_ = 0;
  std::vector<int> cell_start_;  // CSR: trees of cell c are cell_trees_[start[c], start[c+1])
  std::vector<int> cell_trees_;
};

}  // namespace canopy::agents
