#pragma once
// Scripted paths: where a body should be at time t. Targets are driven along them by velocity,
// and UAVs may follow one as a scripted sensor sweep.
#include <vector>

#include "core/types.h"

namespace canopy::world {

/// A point of a timed path: be at p (m) at time t (s).
struct TimedPoint {
  double t = 0.0;
  Vec2 p = Vec2::Zero();
};

/// A piecewise-linear path through timed points (timed waypoints or a recorded track), or a
/// constant-velocity motion. Before the first point the body waits at it, after the last it
/// stays at the last one.
class Path {
 public:
  Path() = default;
  /// points: at least one, with strictly increasing t (validated by the scenario loader).
  static Path throughPoints(std::vector<TimedPoint> points);
  /// p(t) = start + velocity · t.
  static Path constantVelocity(const Vec2& start, const Vec2& velocity);

  Vec2 positionAt(double t) const;  // m
  Vec2 velocityAt(double t) const;  // m/s, the velocity of the segment that starts at or before t
  const std::vector<TimedPoint>& points() const { return points_; }
  bool isConstantVelocity() const { return points_.empty(); }
  const Vec2& start() const { return start_; }
  const Vec2& velocity() const { return velocity_; }

 private:
  std::vector<TimedPoint> points_;  // empty for constant velocity
  Vec2 start_ = Vec2::Zero();       // constant velocity only
  Vec2 velocity_ = Vec2::Zero();    // constant velocity only
};

}  // namespace canopy::world
