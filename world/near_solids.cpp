#include "world/near_solids.h"

#include <algorithm>
#include <cmath>

namespace canopy::world {
namespace {

// A solid whose bounds cover more cells than this (a long wall) is kept out of the grid and
// tested on every query instead.
constexpr std::int64_t kMaxCellsPerSolid = 64;
// Cell indices are clamped here (2³⁰ cells of 8 m is far beyond any coordinate Box2D takes).
constexpr double kCellLimit = 1 << 30;

std::int64_t cellOf(double x) {
  return static_cast<std::int64_t>(
      std::floor(std::clamp(x / NearSolids::kCell, -kCellLimit, kCellLimit)));
}

std::uint64_t cellKey(std::int64_t column, std::int64_t row) {
  const auto biased = [](std::int64_t c) { return static_cast<std::uint64_t>(c + (1LL << 31)); };
  return biased(column) << 32 | biased(row);
}

// The bounds of a tree's solid part: the wall polygon's box, or the trunk's.
Aabb solidBounds(const TreeDef& tree) {
  if (isWall(tree)) return bounds(tree);
  const Vec2 r(tree.trunk_radius, tree.trunk_radius);
  return {tree.centre - r, tree.centre + r};
}

bool overlaps(const Aabb& a, const Aabb& b) {
  return a.lo.x() <= b.hi.x() && b.lo.x() <= a.hi.x() && a.lo.y() <= b.hi.y() &&
         b.lo.y() <= a.hi.y();
}

}  // namespace

NearSolids::NearSolids(const std::vector<TreeDef>& trees)
    : bounds_(trees.size()), users_(trees.size(), 0) {
  for (std::size_t k = 0; k < trees.size(); ++k) {
    const TreeDef& tree = trees[k];
    if (!isWall(tree) && !(tree.trunk_radius > 0.0)) continue;
    const Aabb box = solidBounds(tree);
    bounds_[k] = box;
    const std::int64_t x0 = cellOf(box.lo.x()), x1 = cellOf(box.hi.x());
    const std::int64_t y0 = cellOf(box.lo.y()), y1 = cellOf(box.hi.y());
    if ((x1 - x0 + 1) * (y1 - y0 + 1) > kMaxCellsPerSolid) {
      large_.push_back(static_cast<int>(k));
      continue;
    }
    for (std::int64_t x = x0; x <= x1; ++x)
      for (std::int64_t y = y0; y <= y1; ++y) grid_.push_back({cellKey(x, y), static_cast<int>(k)});
  }
  std::sort(grid_.begin(), grid_.end(), [](const CellEntry& a, const CellEntry& b) {
    return a.cell < b.cell || (a.cell == b.cell && a.tree < b.tree);
  });
}

void NearSolids::query(const Aabb& box, std::vector<int>& out) const {
  const auto byCell = [](const CellEntry& e, std::uint64_t cell) { return e.cell < cell; };
  const std::int64_t y0 = cellOf(box.lo.y()), y1 = cellOf(box.hi.y());
  // Keys sort by column, then row: one column's rows y0..y1 are one run of the grid.
  for (std::int64_t x = cellOf(box.lo.x()); x <= cellOf(box.hi.x()); ++x) {
    auto it = std::lower_bound(grid_.begin(), grid_.end(), cellKey(x, y0), byCell);
    const std::uint64_t last = cellKey(x, y1);
    for (; it != grid_.end() && it->cell <= last; ++it)
      if (overlaps(bounds_[it->tree], box)) out.push_back(it->tree);
  }
  for (const int k : large_)
    if (overlaps(bounds_[k], box)) out.push_back(k);
}

void NearSolids::update(int robot, const Vec2& p, double radius, double travel,
                        std::vector<int>& added, std::vector<int>& removed) {
  if (robot >= static_cast<int>(near_.size())) near_.resize(robot + 1);
  Neighbourhood& n = near_[robot];
  if (n.valid && (p - n.anchor).norm() + travel <= n.skin) return;  // it cannot leave it yet

  n.valid = true;
  n.anchor = p;
  n.skin = std::max(kMinSkin, 2.0 * travel);
  const double reach = radius + n.skin + kFloatMargin;  // m
  const Vec2 half(reach, reach);
  scratch_.clear();
  query(Aabb{p - half, p + half}, scratch_);
  std::sort(scratch_.begin(), scratch_.end());
  scratch_.erase(std::unique(scratch_.begin(), scratch_.end()), scratch_.end());

  // Walk the old and new lists together: in the new only → one more user; in the old only →
  // one fewer. A solid enters the world with its first user and leaves it with its last.
  std::size_t i = 0, j = 0;
  const std::vector<int>& old = n.solids;
  while (i < old.size() || j < scratch_.size()) {
    if (j == scratch_.size() || (i < old.size() && old[i] < scratch_[j])) {
      if (--users_[old[i]] == 0) {
        removed.push_back(old[i]);
        --held_;
      }
      ++i;
    } else if (i == old.size() || scratch_[j] < old[i]) {
      if (users_[scratch_[j]]++ == 0) {
        added.push_back(scratch_[j]);
        ++held_;
      }
      ++j;
    } else {
      ++i;
      ++j;
    }
  }
  n.solids.swap(scratch_);
}

}  // namespace canopy::world
