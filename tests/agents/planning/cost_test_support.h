#pragma once
// Small builders shared by the NBO cost's tests: a hovering UAV, a target's Gaussian and the
// cost's settings.
#include "agents/planning/nominal_cost.h"

namespace canopy::agents::planning::cost_test {

inline UavState hoveringUav(Vec2 position) {
  UavState u;
  u.position = position;
  return u;
}

// ξ = (position, velocity), P = variance · I₄.
inline TargetGaussian target(Vec2 position, Vec2 velocity, double variance = 1.0) {
  TargetGaussian t;
  t.x << position, velocity;
  t.P = variance * Mat4::Identity();
  return t;
}

inline CostSettings settings(int horizon, bool terminal) {
  CostSettings s;
  s.horizon = horizon;
  s.terminal_penalty = terminal;
  return s;
}

}  // namespace canopy::agents::planning::cost_test
