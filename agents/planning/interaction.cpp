// Which UAVs' plans can interact over a planning horizon (agents/planning/interaction.h).
#include "agents/planning/interaction.h"

#include "agents/planning/altitude_choice.h"

#include <algorithm>

namespace canopy::agents::planning {

double reachOf(const CostSettings& s, const UavState& u) {
  const int T = s.horizon * s.substeps;
  const double tau = s.period / s.substeps;
  // A camera that may climb: the circumradius of its largest footprint within the horizon.
  return T * u.v_max * tau + sensing::circumradius(u.footprint) * footprintGrowth(u, T * tau);
}

bool keepsClear(const UavState& u) {
  return u.kind == world::AgentKind::ground || u.radius > 0.0;
}

bool sameClass(const UavState& a, const UavState& b) {
  return (a.kind == world::AgentKind::ground) == (b.kind == world::AgentKind::ground);
}

bool mayTouch(const PlanningProblem& problem, std::span<const int> free_agents, int i) {
  const CostSettings& s = problem.settings;
  const UavState& fixed = problem.uavs[i];
  if (!s.keep_clear || !keepsClear(fixed)) return false;
  const double travel = s.period * s.horizon;  // T·τ = H·Δ
  for (const int f : free_agents) {
    const UavState& free = problem.uavs[f];
    if (!keepsClear(free) || !sameClass(free, fixed)) continue;
    const double room = travel * (free.v_max + fixed.v_max) + free.radius + fixed.radius +
                        s.clearance + kReachSlack;
    if ((fixed.position - free.position).norm() <= room) return true;
  }
  return false;
}

std::vector<int> interactingBlocks(const PlanningProblem& problem, int self,
                                   std::span<const int> order) {
  const CostSettings& s = problem.settings;
  const int n = static_cast<int>(problem.uavs.size());
  double track_speed = 0.0;  // m/s, max_j |v_j|
  for (const TargetGaussian& target : problem.targets)
    track_speed = std::max(track_speed, target.x.tail<2>().norm());
  const double track_travel = s.period * s.horizon * track_speed;  // T·τ·max_j |v_j|
  auto linked = [&](int i, int k) {
    const double apart = (problem.uavs[i].position - problem.uavs[k].position).norm();
    const int only_i[] = {i};
    return apart <= reachOf(s, problem.uavs[i]) + reachOf(s, problem.uavs[k]) + track_travel +
                        kReachSlack ||
           mayTouch(problem, only_i, k);
  };
  // Breadth-first from self over the n² links (n is the team: a few hundred at most).
  std::vector<char> in_component(n, 0);
  std::vector<int> frontier{self};
  in_component[self] = 1;
  while (!frontier.empty()) {
    const int i = frontier.back();
    frontier.pop_back();
    for (int k = 0; k < n; ++k) {
      if (in_component[k] || !linked(i, k)) continue;
      in_component[k] = 1;
      frontier.push_back(k);
    }
  }
  std::vector<int> blocks;
  for (const int i : order)
    if (in_component[i]) blocks.push_back(i);
  return blocks;
}

}  // namespace canopy::agents::planning
