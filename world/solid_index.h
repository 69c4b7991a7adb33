#pragma once
// The solid parts of a list of trees (a wall's polygon, a trunk's disc) in a uniform grid of their
// bounding boxes, about one solid per cell: which solids may meet a box, in time that grows with
// the box and not with the forest. validate's check of target paths (spec/solid_paths.h) and the
// world's solids near its robots (world/near_solids.h) ask it.
#include <cstdint>
#include <vector>

#include "core/types.h"
#include "world/tree.h"

namespace canopy::world {

/// The bounds of a tree's solid part: the wall polygon's box, or the trunk's.
Aabb solidBounds(const TreeDef& tree);

class SolidIndex {
 public:
  /// Indexes every tree with a solid part (a wall, or a trunk of positive radius); reports
  /// progress for a large forest.
  explicit SolidIndex(const std::vector<TreeDef>& trees);

  /// Appends to `out` the indices (in the trees given) of the solids whose bounds meet `box`,
  /// ascending, each once.
  void near(const Aabb& box, std::vector<int>& out) const;

 private:
  std::int64_t cellOf(double x) const;
  static std::uint64_t cellKey(std::int64_t column, std::int64_t row);

  std::vector<int> solids_;   // indices in the trees, ascending
  std::vector<Aabb> bounds_;  // per tree: its solid part's bounds (unset when it has none)
  std::vector<int> wide_;     // solids over kMaxCellsPerSolid cells: tested on every look
  double cell_ = 1.0;         // m
  struct CellEntry {
    std::uint64_t cell;  // cellKey(column, row): one column's rows are one run
    int tree;
  };
  std::vector<CellEntry> cells_;  // sorted by cell, then tree
};

}  // namespace canopy::world
