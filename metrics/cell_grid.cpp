#include "metrics/cell_grid.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace canopy::metrics {

void CellGrid::build(std::span<const Vec2> points, double side) {
  side_ = side;
  points_.assign(points.begin(), points.end());
  order_.clear();
  usable_ = false;
  if (!(side >= 1e-3)) return;  // cells would be numbered beyond 64 bits
  std::int64_t x1 = 0, y1 = 0;
  bool any = false;
  for (const Vec2& p : points_) {
    if (!searchable(p)) continue;
    const std::int64_t cx = cellOf(p.x()), cy = cellOf(p.y());
    x0_ = any ? std::min(x0_, cx) : cx;
    y0_ = any ? std::min(y0_, cy) : cy;
    x1 = any ? std::max(x1, cx) : cx;
    y1 = any ? std::max(y1, cy) : cy;
    any = true;
  }
  if (!any) {  // no point in any cell: an empty grid
    x0_ = y0_ = 0;
    width_ = height_ = 0;
    start_.assign(1, 0);
    usable_ = true;
    return;
  }
  width_ = x1 - x0_ + 1;
  height_ = y1 - y0_ + 1;
  // |coordinate| < 1e15 and side ≥ 1e-3 bound each extent by 2e18 + 1 cells: no overflow.
  usable_ = width_ <= kMaxCells && height_ <= kMaxCells / width_;
  if (!usable_) return;

  // A counting sort of the points by cell, column by column. start_[c] first counts cell c's
  // points, then (summed) the end of its run; placing the points from the last index down moves
  // it to the run's start, and leaves each run in index order.
  const auto cells = static_cast<std::size_t>(width_ * height_);
  start_.assign(cells + 1, 0);
  auto cellIndex = [&](const Vec2& p) {
    return static_cast<std::size_t>((cellOf(p.x()) - x0_) * height_ + (cellOf(p.y()) - y0_));
  };
  for (const Vec2& p : points_)
    if (searchable(p)) ++start_[cellIndex(p)];
  std::partial_sum(start_.begin(), start_.end() - 1, start_.begin());
  start_.back() = cells == 0 ? 0 : start_[cells - 1];
  order_.resize(static_cast<std::size_t>(start_.back()));
  for (int j = static_cast<int>(points_.size()) - 1; j >= 0; --j)
    if (searchable(points_[j])) order_[static_cast<std::size_t>(--start_[cellIndex(points_[j])])] = j;
}

}  // namespace canopy::metrics
