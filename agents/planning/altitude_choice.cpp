#include "agents/planning/altitude_choice.h"

#include <algorithm>
#include <vector>

namespace canopy::agents::planning {

double meanAltitude(const UavState& uav, double climb, int horizon, double period) {
  double sum = 0.0;
  for (int m = 1; m <= horizon; ++m)
    sum += std::clamp(uav.z + climb * m * period, uav.z_min, uav.z_max);  // z_m
  return horizon > 0 ? sum / horizon : uav.z;
}

UavState atAltitude(const UavState& uav, double z) {
  UavState out = uav;
  out.z = z;
  if (!uav.camera) return out;
  out.footprint = sensing::groundFootprint(*uav.camera, z);
  // α(z) = α_ref · ℓ(z) / ℓ(h_ref) at the ground point straight below: z / h_ref.
  out.quality.alpha = uav.reference_alpha * (z / sensing::kDefaultAltitude);
  return out;
}

double chooseClimb(const PlanningProblem& problem, int agent, std::span<const Plan> joint,
                   const Plan& own, double period, NominalCost& cost) {
  const UavState& uav = problem.uavs[static_cast<std::size_t>(agent)];
  if (!uav.camera || !(uav.z_min < uav.z_max) || !(uav.climb_rate > 0.0)) return 0.0;
  const int H = problem.settings.horizon;
  std::vector<UavState> uavs(problem.uavs.begin(), problem.uavs.end());
  PlanningProblem at = problem;
  std::vector<Vec2> actions(static_cast<std::size_t>(H));
  for (int m = 0; m < H; ++m) actions[static_cast<std::size_t>(m)] = own.action(m);
  const int free_agents[] = {agent};
  double best_climb = 0.0, best_cost = 0.0;
  bool first = true;
  for (const double fraction : kClimbFractions) {
    const double climb = fraction * uav.climb_rate;
    uavs[static_cast<std::size_t>(agent)] = atAltitude(uav, meanAltitude(uav, climb, H, period));
    at.uavs = uavs;
    cost.prepare(at, free_agents, joint);
    const double J = cost.evaluate(actions);
    if (first || J < best_cost) {
      best_cost = J;
      best_climb = climb;
      first = false;
    }
  }
  return best_climb;
}

}  // namespace canopy::agents::planning
