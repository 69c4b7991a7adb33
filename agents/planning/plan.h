#pragma once
// A plan: H velocity commands, one per planning step Δ (receding horizon, algorithms.md §1).
#include <span>
#include <vector>

#include "agents/planning/uav_state.h"
#include "core/types.h"

namespace canopy::agents::planning {

struct Plan {
  std::vector<Vec2> velocities;  // m/s, a_{i,1..H}; only the first is applied
  double cost = 0.0;  // m² (J of the joint plan it was chosen with, on the planner's belief)
  // m/s, climb rates c_{i,1..H} of a UAV whose altitude is free (issue 53); empty: it holds its
  // altitude. Only the first is applied, as for the velocities.
  std::vector<double> climbs = {};

  /// The command to apply now: the first action, or hover for an empty plan.
  Vec2 command() const { return velocities.empty() ? Vec2::Zero() : velocities.front(); }
  /// Action m (0-based) with the intention rule: a missing step repeats the last action; an empty
  /// plan hovers.
  Vec2 action(int m) const;
  /// Climb rate m (0-based) by the same rule: a missing step repeats the last; none: 0 (hold).
  double climb(int m) const;
};

/// The intention a plan leaves `actions` actions later (paper eq. 7): the plan shifted by that
/// many actions, padded to `horizon` actions by repeating its last action; an empty plan gives
/// hovering. The result's cost is 0 (it was not optimised). A whole shift k moves action m + k to
/// m. A fractional shift k + f (re-planning inside an action) gives each new action the mean
/// velocity over its interval, (1 − f)·a_{m+k} + f·a_{m+k+1}, so that the new plan reaches the
/// old plan's ground points at the new plan instants exactly. Climb rates shift the same way
/// (none stay none).
Plan shiftedPlan(const Plan& plan, double actions, int horizon);

/// A plan of `horizon` zero velocities.
Plan hoverPlan(int horizon);

/// The ground points p_{i,1..H} the plan visits from `uav`'s position, p_{i,m} = p_{i,m−1} +
/// a_{i,m}·Δ, with each action clamped to v_max as the world does (m).
std::vector<Vec2> plannedPath(const UavState& uav, const Plan& plan, double period);

}  // namespace canopy::agents::planning
