#include "agents/planning/plan.h"

#include <algorithm>
#include <cmath>

#include "world/unicycle.h"

namespace canopy::agents::planning {

Vec2 Plan::action(int m) const {
  if (velocities.empty()) return Vec2::Zero();
  return velocities[std::min<std::size_t>(std::max(m, 0), velocities.size() - 1)];
}

double Plan::climb(int m) const {
  if (climbs.empty()) return 0.0;
  return climbs[std::min<std::size_t>(std::max(m, 0), climbs.size() - 1)];
}

Plan shiftedPlan(const Plan& plan, double actions, int horizon) {
  const double whole = std::floor(actions);
  const int k = static_cast<int>(whole);
  const double f = actions - whole;  // the part of action k already flown, in [0, 1)
  Plan shifted;
  shifted.velocities.reserve(horizon);
  for (int m = 0; m < horizon; ++m) {
    if (f == 0.0) {
      shifted.velocities.push_back(plan.action(m + k));
    } else {
      // mean velocity over [t + (m + k + f)·Δ, t + (m + k + 1 + f)·Δ]
      shifted.velocities.push_back((1.0 - f) * plan.action(m + k) + f * plan.action(m + k + 1));
    }
  }
  if (plan.climbs.empty()) return shifted;
  shifted.climbs.reserve(horizon);
  for (int m = 0; m < horizon; ++m) {  // the mean climb rate over the same interval
    shifted.climbs.push_back(f == 0.0 ? plan.climb(m + k)
                                      : (1.0 - f) * plan.climb(m + k) + f * plan.climb(m + k + 1));
  }
  return shifted;
}

Plan hoverPlan(int horizon) {
  Plan plan;
  plan.velocities.assign(horizon, Vec2::Zero());
  return plan;
}

std::vector<Vec2> plannedPath(const UavState& uav, const Plan& plan, double period) {
  std::vector<Vec2> path;
  path.reserve(plan.velocities.size());
  world::Pose2 pose{uav.position, uav.yaw};
  for (Vec2 a : plan.velocities) {
    const double speed = a.norm();
    if (speed > uav.v_max) a *= uav.v_max / speed;  // |a| ≤ v_max
    if (uav.kind == world::AgentKind::ground) {
      pose = world::unicycleMove(pose, a, uav.turn_rate, period);  // turn, then drive
    } else {
      pose.position += a * period;  // p_{i,m} = p_{i,m−1} + a_{i,m}·Δ
    }
    path.push_back(pose.position);
  }
  return path;
}

}  // namespace canopy::agents::planning
