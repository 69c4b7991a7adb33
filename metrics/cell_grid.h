#pragma once
// A grid of square cells of side c over one point set, built once and searched many times: the
// people's positions, against which every agent's tracks are scored at each step. Two points
// closer than c lie in the same or neighbouring cells, so the points near p are those in the
// 3 × 3 cells around p's.
//
// The grid is dense over the set's bounding box: cell (x, y) is number (x − x₀)·H + (y − y₀),
// column by column, and its points are a run of one array (a counting sort), so the three cells
// of a column are one run and a search costs three look-ups. A set whose box would need more than
// kMaxCells cells has no grid (usable() is false) and callers search another way.
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "core/types.h"

namespace canopy::metrics {

class CellGrid {
 public:
  static constexpr std::int64_t kMaxCells = std::int64_t{1} << 20;  // 4 MB of run starts

  /// The grid of cells of side `side` over a copy of points. Points that are not finite or lie
  /// 1e15 m or more from the origin on an axis are in no cell. A side under 1 mm gives no grid.
  void build(std::span<const Vec2> points, double side);

  bool usable() const { return usable_; }
  double side() const { return side_; }
  std::span<const Vec2> points() const { return points_; }

  /// Whether p can be searched for (finite and nearer than 1e15 m on each axis).
  static bool searchable(const Vec2& p) { return p.allFinite() && p.cwiseAbs().maxCoeff() < 1e15; }

  /// visit(j) for each point j in the 3 × 3 cells around searchable p's cell: column by column,
  /// and within a column by cell, then by index. Only when usable().
  template <class Visit>
  void forEachNear(const Vec2& p, Visit&& visit) const {
    const std::int64_t cx = cellOf(p.x()), cy = cellOf(p.y());
    if (cy + 1 < y0_ || cy - 1 > y0_ + height_ - 1) return;
    const std::int64_t low = (cy - 1 < y0_ ? y0_ : cy - 1) - y0_;
    const std::int64_t high = (cy + 1 > y0_ + height_ - 1 ? y0_ + height_ - 1 : cy + 1) - y0_;
    for (std::int64_t x = cx - 1; x <= cx + 1; ++x) {
      if (x < x0_ || x >= x0_ + width_) continue;
      const std::int64_t column = (x - x0_) * height_;
      const int last = start_[static_cast<std::size_t>(column + high + 1)];
      for (int k = start_[static_cast<std::size_t>(column + low)]; k < last; ++k) visit(order_[k]);
    }
  }

 private:
  std::int64_t cellOf(double coordinate) const {
    return static_cast<std::int64_t>(std::floor(coordinate / side_));
  }

  double side_ = 1.0;
  bool usable_ = false;
  std::vector<Vec2> points_;
  std::int64_t x0_ = 0, y0_ = 0, width_ = 0, height_ = 0;  // the box, in cells
  std::vector<int> start_;  // per cell, its first entry of order_; one more at the end
  std::vector<int> order_;  // the points in cells, by cell, then by index
};

}  // namespace canopy::metrics
