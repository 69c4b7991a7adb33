#pragma once
// A ground robot's motion: a unicycle that turns in place toward the commanded direction at its
// turn-rate limit, then drives straight along it. The one source of this motion: the world moves
// ground robots with it and the planner's cost predicts them with it.
#include <algorithm>
#include <cmath>

#include "core/angles.h"
#include "core/types.h"

namespace canopy::world {

/// A pose on the ground: position and heading.
struct Pose2 {
  Vec2 position = Vec2::Zero();  // m
  double heading = 0.0;          // rad, ψ
};

/// Below this commanded speed (m/s) a robot holds its pose, as a UAV holds its yaw.
inline constexpr double kUnicycleHoverSpeed = 1e-6;

/// The pose after holding the velocity command c (|c| ≤ v_max already) for t seconds from `pose`,
/// with turn rate at most ω_max (rad/s). With δ = wrap(atan2(c) − ψ) and t_r = |δ|/ω_max:
///   ψ(t) = ψ + sign(δ) ω_max min(t, t_r),   p(t) = p + |c| max(0, t − t_r) ĉ.
/// Exact for a command held constant, and composes: moving by t₁ then by t₂ gives the pose of
/// t₁ + t₂, so the world's steps and the planner's samples agree at every step boundary.
inline Pose2 unicycleMove(const Pose2& pose, const Vec2& c, double turn_rate, double t) {
  const double speed = c.norm();
  if (speed < kUnicycleHoverSpeed || t <= 0.0) return pose;
  const double goal = std::atan2(c.y(), c.x());
  const double delta = wrapAngle(goal - pose.heading);
  const double turn_time = std::abs(delta) / turn_rate;  // t_r (s)
  Pose2 out;
  if (t < turn_time) {  // still turning in place
    out.position = pose.position;
    out.heading = wrapAngle(pose.heading + std::copysign(turn_rate * t, delta));
    return out;
  }
  out.heading = goal;
  out.position = pose.position + (t - turn_time) * c;  // |c| (t − t_r) ĉ
  return out;
}

}  // namespace canopy::world
