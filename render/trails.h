#pragma once
// Short trails of the targets' true positions, for the frames.
#include <vector>

#include "core/types.h"
#include "world/snapshot.h"

namespace canopy::render {

/// Seconds of history a trail shows by default.
inline constexpr double kDefaultTrailSeconds = 5.0;

class TargetTrails {
 public:
  explicit TargetTrails(double seconds = kDefaultTrailSeconds) : seconds_(seconds) {}

  /// Appends every target's position at the snapshot and forgets those older than `seconds`.
  /// Call it every step (not only on frames); a change in the number of targets restarts.
  void add(const world::WorldSnapshot& truth);

  int targets() const { return static_cast<int>(points_.size()); }
  /// Target t's recent positions (m), oldest first; empty for an unknown target.
  const std::vector<Vec2>& trail(int target) const;

 private:
  double seconds_;                         // s
  std::vector<double> times_;              // s, shared by every target's points
  std::vector<std::vector<Vec2>> points_;  // points_[t][n] at times_[n]
};

}  // namespace canopy::render
