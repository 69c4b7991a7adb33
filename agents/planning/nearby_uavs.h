#pragma once
// The fixed UAVs that may hold a point at one sample of the horizon, found through a uniform grid
// instead of asking every UAV (issue 48): NominalCost::prepare asked each of 255 fixed UAVs
// about each of 1024 tracks at every sample, 10 % of a 256-UAV run.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "core/types.h"

namespace canopy::agents::planning {

/// UAVs at positions p_i, bucketed into square cells of side `reach` (sorted by cell, then index).
/// near(z) lists, by increasing index, every UAV with |p_i − z| ≤ reach, and possibly others of
/// the 3 × 3 cells around z: a superset for a test that holds only within reach of p_i.
class NearbyUavs {
 public:
  /// False (and the index unusable) when the cells would not fit 32-bit coordinates, e.g. a
  /// reach far smaller than the UAVs' spread; the caller then asks every UAV.
  bool build(std::span<const int> uavs, std::span<const Vec2> position_of, double reach) {
    entries_.clear();
    if (uavs.empty() || !(reach > 0.0) || !std::isfinite(reach)) return false;
    cell_ = reach;
    origin_ = position_of[uavs.front()];
    for (const int i : uavs) origin_ = origin_.cwiseMin(position_of[i]);
    for (const int i : uavs) {
      const Vec2 d = (position_of[i] - origin_) / cell_;
      if (!(d.x() < kMaxCell && d.y() < kMaxCell)) return false;
      entries_.push_back({key(static_cast<std::int64_t>(d.x()), static_cast<std::int64_t>(d.y())),
                          i});
    }
    std::sort(entries_.begin(), entries_.end());
    return true;
  }

  /// Appends to `out` (cleared first) the UAVs of the 3 × 3 cells around z, by increasing index.
  void near(const Vec2& z, std::vector<int>& out) const {
    out.clear();
    const Vec2 d = (z - origin_) / cell_;
    // z beyond the grid by more than a cell: no UAV within reach (and no overflow below).
    if (!(d.x() >= -1.0 && d.y() >= -1.0 && d.x() < kMaxCell + 1.0 && d.y() < kMaxCell + 1.0))
      return;
    const auto cx = static_cast<std::int64_t>(std::floor(d.x()));
    const auto cy = static_cast<std::int64_t>(std::floor(d.y()));
    for (std::int64_t y = cy - 1; y <= cy + 1; ++y) {
      if (y < 0) continue;
      // A row's three cells are consecutive keys.
      const auto first = std::lower_bound(entries_.begin(), entries_.end(),
                                          Entry{key(std::max<std::int64_t>(cx - 1, 0), y), -1});
      const auto last = std::lower_bound(first, entries_.end(), Entry{key(cx + 2, y), -1});
      for (auto e = first; e != last; ++e) out.push_back(e->uav);
    }
    std::sort(out.begin(), out.end());
  }

 private:
  static constexpr double kMaxCell = 1 << 30;  // cells per axis
  static std::int64_t key(std::int64_t x, std::int64_t y) { return (y << 32) + x; }
  struct Entry {
    std::int64_t key;
    int uav;
    bool operator<(const Entry& other) const {
      return std::pair(key, uav) < std::pair(other.key, other.uav);
    }
  };
  double cell_ = 1.0;  // m
  Vec2 origin_ = Vec2::Zero();
  std::vector<Entry> entries_;
};

}  // namespace canopy::agents::planning
