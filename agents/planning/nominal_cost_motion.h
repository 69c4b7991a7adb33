#pragma once
// How the NBO cost moves a UAV through its H actions (NominalCost::fly): as the world moves it,
// |a| clamped to v_max, the yaw following the velocity where the UAV's yaw mode says so, a ground
// robot as the world's unicycle. Both prepare() (the fixed UAVs) and evaluate() (the free ones,
// four candidates at a time) replay it; it is always inlined into them (nominal_cost.cpp,
// nominal_cost_evaluate.cpp).
#include <cmath>
#include <span>

#include "agents/planning/nominal_cost.h"
#include "core/lanes.h"
#include "world/unicycle.h"

namespace canopy::agents::planning {

template <class Sink>
[[gnu::always_inline]] inline void NominalCost::fly(const Mover& uav, std::span<const Vec2> actions,
                                                    Sink&& sink) const {
  constexpr double kHoverSpeedSquared = 1e-12;  // m²/s², below this the yaw is kept (as the world)
  if (uav.ground) {
    driveUnicycle(uav, actions, sink);
    return;
  }
  Vec2 p = uav.position;
  double c = uav.cos_yaw, s = uav.sin_yaw;
  const double v_max_sq = uav.v_max * uav.v_max;
  const double tau = period_ / substeps_;  // s, between samples
  int t = 0;
  for (int m = 0; m < horizon_; ++m) {
    Vec2 a = actions[m];
    double speed_sq = a.squaredNorm();
    if (speed_sq > v_max_sq) {  // the world clamps |a| to v_max
      a *= uav.v_max / std::sqrt(speed_sq);
      speed_sq = v_max_sq;
    }
    if (uav.yaw_follows && speed_sq > kHoverSpeedSquared) {
      const double speed = std::sqrt(speed_sq);
      c = a.x() / speed;  // ψ = atan2(a_y, a_x), kept as (cos ψ, sin ψ)
      s = a.y() / speed;
    }
    const Vec2 step = a * tau;  // m per sample
    for (int sample = 0; sample < substeps_; ++sample) {
      p += step;  // p at t_{m−1} + s·τ; at the last sample p_{i,m} = p_{i,m−1} + a_{i,m}·Δ
      sink(t++, p, Vec2(c, s));
    }
  }
}

[[gnu::always_inline]] inline void NominalCost::flyLanes(const Mover& uav,
                                                         const Vec2* const (&plans)[kLanes],
                                                         PoseLanes* poses) const {
  // fly()'s operations in the same order, each on four lanes; its branches become selects.
  using lanes::V4;
  using lanes::M4;
  constexpr double kHoverSpeedSquared = 1e-12;  // as fly()
  V4 px = lanes::broadcast(uav.position.x()), py = lanes::broadcast(uav.position.y());
  V4 c = lanes::broadcast(uav.cos_yaw), s = lanes::broadcast(uav.sin_yaw);
  const double v_max_sq = uav.v_max * uav.v_max;
  const double tau = period_ / substeps_;  // s, between samples
  int t = 0;
  for (int m = 0; m < horizon_; ++m) {
    V4 ax = {plans[0][m].x(), plans[1][m].x(), plans[2][m].x(), plans[3][m].x()};
    V4 ay = {plans[0][m].y(), plans[1][m].y(), plans[2][m].y(), plans[3][m].y()};
    V4 speed_sq = ax * ax + ay * ay;
    const M4 clamped = speed_sq > v_max_sq;  // the world clamps |a| to v_max
    if (lanes::anyLane(clamped)) {
      const V4 factor = uav.v_max / lanes::sqrt(speed_sq);
      ax = clamped ? ax * factor : ax;
      ay = clamped ? ay * factor : ay;
      speed_sq = clamped ? lanes::broadcast(v_max_sq) : speed_sq;
    }
    if (uav.yaw_follows) {  // ψ = atan2(a_y, a_x) where the UAV moves, kept where it hovers
      const M4 moving = speed_sq > kHoverSpeedSquared;
      const V4 speed = lanes::sqrt(speed_sq);
      c = moving ? ax / speed : c;
      s = moving ? ay / speed : s;
    }
    const V4 step_x = ax * tau, step_y = ay * tau;  // m per sample
    for (int sample = 0; sample < substeps_; ++sample, ++t) {
      px += step_x;
      py += step_y;
      poses[t] = {px, py, c, s};
    }
  }
}

template <class Sink>
void NominalCost::driveUnicycle(const Mover& robot, std::span<const Vec2> actions,
                                Sink&& sink) const {
  world::Pose2 pose{robot.position, robot.yaw};
  const double tau = period_ / substeps_;  // s, between samples
  int t = 0;
  for (int m = 0; m < horizon_; ++m) {
    Vec2 a = actions[m];
    const double speed = a.norm();
    if (speed > robot.v_max) a *= robot.v_max / speed;  // the world clamps |a| to v_max
    world::Pose2 at;
    for (int sample = 1; sample <= substeps_; ++sample) {
      at = world::unicycleMove(pose, a, robot.turn_rate, sample * tau);  // the world's motion
      sink(t++, at.position, Vec2(std::cos(at.heading), std::sin(at.heading)));
    }
    pose = at;
  }
}

}  // namespace canopy::agents::planning
