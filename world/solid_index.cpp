#include "world/solid_index.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/progress.h"

namespace canopy::world {
namespace {

// A solid whose bounds cover more cells than this (a long wall) stays out of the grid.
constexpr std::int64_t kMaxCellsPerSolid = 1024;
// Cell indices are clamped to ±2³⁰, far beyond any coordinate Box2D takes.
constexpr double kCellLimit = 1 << 30;

bool overlaps(const Aabb& a, const Aabb& b) {
  return a.lo.x() <= b.hi.x() && b.lo.x() <= a.hi.x() && a.lo.y() <= b.hi.y() &&
         b.lo.y() <= a.hi.y();
}

}  // namespace

Aabb solidBounds(const TreeDef& tree) {
  if (isWall(tree)) return bounds(tree);
  const Vec2 r(tree.trunk_radius, tree.trunk_radius);
  return {tree.centre - r, tree.centre + r};
}

SolidIndex::SolidIndex(const std::vector<TreeDef>& trees) : bounds_(trees.size()) {
  Aabb all{Vec2::Constant(std::numeric_limits<double>::infinity()),
           Vec2::Constant(-std::numeric_limits<double>::infinity())};
  for (int k = 0; k < static_cast<int>(trees.size()); ++k) {
    if (!isWall(trees[k]) && !(trees[k].trunk_radius > 0.0)) continue;
    solids_.push_back(k);
    bounds_[k] = solidBounds(trees[k]);
    all = {all.lo.cwiseMin(bounds_[k].lo), all.hi.cwiseMax(bounds_[k].hi)};
  }
  if (solids_.empty()) return;
  // About one solid per cell on average.
  const Vec2 extent = all.hi - all.lo;
  cell_ = std::max(1.0, std::sqrt(extent.x() * extent.y() / static_cast<double>(solids_.size())));
  ProgressCounter progress("indexing trunks and walls", static_cast<double>(solids_.size()));
  for (const int k : solids_) {
    progress.add();
    const Aabb& box = bounds_[k];
    const std::int64_t x0 = cellOf(box.lo.x()), x1 = cellOf(box.hi.x());
    const std::int64_t y0 = cellOf(box.lo.y()), y1 = cellOf(box.hi.y());
    if ((x1 - x0 + 1) * (y1 - y0 + 1) > kMaxCellsPerSolid) {
      wide_.push_back(k);
      continue;
    }
    for (std::int64_t x = x0; x <= x1; ++x)
      for (std::int64_t y = y0; y <= y1; ++y) cells_.push_back({cellKey(x, y), k});
  }
  // One sorted array rather than a hash map of lists: 10⁶ trunks are one allocation, not 10⁶.
  std::sort(cells_.begin(), cells_.end(), [](const CellEntry& a, const CellEntry& b) {
    return a.cell < b.cell || (a.cell == b.cell && a.tree < b.tree);
  });
}

std::int64_t SolidIndex::cellOf(double x) const {
  return static_cast<std::int64_t>(std::floor(std::clamp(x / cell_, -kCellLimit, kCellLimit)));
}

std::uint64_t SolidIndex::cellKey(std::int64_t column, std::int64_t row) {
  const auto biased = [](std::int64_t c) { return static_cast<std::uint64_t>(c + (1LL << 31)); };
  return biased(column) << 32 | biased(row);
}

void SolidIndex::near(const Aabb& box, std::vector<int>& out) const {
  if (solids_.empty()) return;
  const std::size_t first = out.size();
  const std::int64_t x0 = cellOf(box.lo.x()), x1 = cellOf(box.hi.x());
  const std::int64_t y0 = cellOf(box.lo.y()), y1 = cellOf(box.hi.y());
  if (static_cast<double>(x1 - x0 + 1) * static_cast<double>(y1 - y0 + 1) >
      static_cast<double>(solids_.size())) {
    // More cells than solids: every solid once is less work.
    for (const int k : solids_)
      if (overlaps(bounds_[k], box)) out.push_back(k);
    return;
  }
  const auto byCell = [](const CellEntry& e, std::uint64_t cell) { return e.cell < cell; };
  for (std::int64_t x = x0; x <= x1; ++x) {  // one column's rows y0 … y1 are one run
    auto it = std::lower_bound(cells_.begin(), cells_.end(), cellKey(x, y0), byCell);
    const std::uint64_t last = cellKey(x, y1);
    for (; it != cells_.end() && it->cell <= last; ++it)
      if (overlaps(bounds_[it->tree], box)) out.push_back(it->tree);
  }
  for (const int k : wide_)
    if (overlaps(bounds_[k], box)) out.push_back(k);
  // A solid over several cells was met once per cell.
  std::sort(out.begin() + static_cast<std::ptrdiff_t>(first), out.end());
  out.erase(std::unique(out.begin() + static_cast<std::ptrdiff_t>(first), out.end()), out.end());
}

}  // namespace canopy::world
