#include "agents/occlusion_map.h"

#include <algorithm>
#include <cmath>

namespace canopy::agents {
namespace {
constexpr int kMaxCells = 1 << 20;  // bounds the index's memory for sparse, wide maps
constexpr int kMaxSide = 1 << 12;   // cells along either side, so a thin map stays bounded too
// Cells per tree at most: an agent's dynamic map holds the few thousand crowns its team has seen,
// spread over a city; a grid of crown-wide cells over their bounds would be mostly empty (10⁶
// cells, 4 MB to clear and sum on every step's rebuild: 14 % of a 64-UAV run's instructions).
constexpr double kCellsPerTree = 16.0;
}  // namespace

OcclusionMap::OcclusionMap(std::vector<world::TreeDef> trees) : trees_(std::move(trees)) {
  if (trees_.empty()) return;
  bounds_ = world::bounds(trees_.front());
  double max_extent = 0.0;
  for (const world::TreeDef& tree : trees_) {
    const Aabb box = world::bounds(tree);
    bounds_.lo = bounds_.lo.cwiseMin(box.lo);
    bounds_.hi = bounds_.hi.cwiseMax(box.hi);
    max_extent = std::max({max_extent, box.width(), box.height()});
  }
  // Cells about one crown wide keep a lookup to a handful of trees; sparse or thin maps get
  // wider cells, so that cols · rows ≤ kMaxSide² and ≈ min(kMaxCells, kCellsPerTree · trees) at
  // most (the index's memory and the work of building it). The answers do not depend on the cell.
  const double cells =
      std::min<double>(kMaxCells, kCellsPerTree * static_cast<double>(trees_.size()));
  cell_ = std::max({max_extent, 1e-3, std::sqrt(bounds_.area() / cells), bounds_.width() / kMaxSide,
                    bounds_.height() / kMaxSide});
  cols_ = std::max(1, static_cast<int>(std::ceil(bounds_.width() / cell_)));
  rows_ = std::max(1, static_cast<int>(std::ceil(bounds_.height() / cell_)));

  // Counting sort of (cell, tree) pairs into CSR arrays: each tree goes into every cell its box
  // touches.
  auto forEachCell = [this](const Aabb& box, auto&& visit) {
    const int c0 =
        std::clamp(static_cast<int>((box.lo.x() - bounds_.lo.x()) / cell_), 0, cols_ - 1);
    const int c1 =
        std::clamp(static_cast<int>((box.hi.x() - bounds_.lo.x()) / cell_), 0, cols_ - 1);
    const int r0 =
        std::clamp(static_cast<int>((box.lo.y() - bounds_.lo.y()) / cell_), 0, rows_ - 1);
    const int r1 =
        std::clamp(static_cast<int>((box.hi.y() - bounds_.lo.y()) / cell_), 0, rows_ - 1);
    for (int r = r0; r <= r1; ++r) {
      for (int c = c0; c <= c1; ++c) visit(r * cols_ + c);
    }
  };
  cell_start_.assign(static_cast<std::size_t>(cols_) * rows_ + 1, 0);
  for (const world::TreeDef& tree : trees_) {
    forEachCell(world::bounds(tree), [this](int cell) { ++cell_start_[cell + 1]; });
  }
  for (std::size_t c = 1; c < cell_start_.size(); ++c) cell_start_[c] += cell_start_[c - 1];
  cell_trees_.resize(cell_start_.back());
  std::vector<int> fill(cell_start_.begin(), cell_start_.end() - 1);
  for (int k = 0; k < static_cast<int>(trees_.size()); ++k) {
    forEachCell(world::bounds(trees_[k]), [&](int cell) { cell_trees_[fill[cell]++] = k; });
  }
}

OcclusionMap OcclusionMap::fromEstimates(const std::vector<TreeEstimate>& trees,
                                         double min_radius) {
  std::vector<world::TreeDef> crowns;
  crowns.reserve(trees.size());
  for (const TreeEstimate& tree : trees) {
    const auto& x = tree.belief.x;  // (cx, cy, r)
    const Vec2 centre(x(0), x(1));
    // A measured outline places the crown's polygon at the estimated centroid, while it stays
    // convex and counter-clockwise (noise could fold a thin one); otherwise its disc.
    std::vector<Vec2> vertices;
    for (int v = 0; v < tree.outline.vertices; ++v) {
      vertices.push_back(centre + tree.outline.offsets[v]);
    }
    if (vertices.size() >= 3 && world::isStrictlyConvex(vertices) &&
        world::signedArea(vertices) > 0.0) {
      crowns.push_back(world::TreeDef::polygon(std::move(vertices)));
    } else {
      crowns.push_back(world::TreeDef::disc(centre, std::max(min_radius, x(2))));
    }
  }
  return OcclusionMap(std::move(crowns));
}

bool OcclusionMap::occludes(const Vec2& p) const {
  if (trees_.empty() || !bounds_.contains(p)) return false;
  const int c = std::min(static_cast<int>((p.x() - bounds_.lo.x()) / cell_), cols_ - 1);
  const int r = std::min(static_cast<int>((p.y() - bounds_.lo.y()) / cell_), rows_ - 1);
  const int cell = r * cols_ + c;
  for (int i = cell_start_[cell]; i < cell_start_[cell + 1]; ++i) {
    if (world::strictlyInside(trees_[cell_trees_[i]], p)) return true;
  }
  return false;
}

bool OcclusionMap::blocksSegment(const Vec2& a, const Vec2& b) const {
  if ((b - a).squaredNorm() < 1e-12) return occludes(a);
  return anyTreeNear(a, b, [&](const world::TreeDef& tree) {
    return world::segmentEntry(tree, a, b) >= 0.0;
  });
}

bool OcclusionMap::blocksSight(const Vec2& a, double ha, const Vec2& b, double hb) const {
  return anyTreeNear(a, b, [&](const world::TreeDef& tree) {
    return world::blocksSight(tree, a, ha, b, hb);
  });
}

bool OcclusionMap::hidesHead(const Vec2& p, double head) const {
  return anyTreeNear(p, p, [&](const world::TreeDef& tree) {
    return tree.base < head && head < tree.top && world::strictlyInside(tree, p);
  });
}

}  // namespace canopy::agents
