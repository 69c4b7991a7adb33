#include "world/substeps.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace canopy::world {

double substepBound(const std::vector<UavDef>& agents, double dt, double target_speed) {
  double fastest = target_speed;  // m/s
  double turn = 0.0;              // rad over the step
  // Per kind: the fastest agent with a body, the smallest body and how many have one.
  struct Bodies {
    double v_max = 0.0, smallest = std::numeric_limits<double>::infinity();
    int count = 0;
  } bodies[2];
  for (const UavDef& agent : agents) {
    fastest = std::max(fastest, agent.v_max);
    const bool ground = agent.kind == AgentKind::ground;
    // A robot turns at its turn rate; a UAV facing its velocity may turn about at once.
    const double agent_turn = ground ? std::min(agent.turn_rate * dt, std::numbers::pi)
                              : agent.yaw_mode == YawMode::velocity ? std::numbers::pi
                                                                    : 0.0;
    turn = std::max(turn, agent_turn);
    if (agent.radius > 0.0) {
      Bodies& b = bodies[ground ? 1 : 0];
      b.v_max = std::max(b.v_max, agent.v_max);
      b.smallest = std::min(b.smallest, agent.radius);
      ++b.count;
    }
  }
  double n = std::max({1.0, std::ceil(fastest * dt / kMaxSubstepTranslation),
                       std::ceil(turn / kMaxSubstepRotation)});
  for (const Bodies& b : bodies) {
    if (b.count >= 2)
      n = std::max(n, std::ceil(2.0 * b.v_max * dt / (kMaxSubstepRadii * b.smallest)));
  }
  return n;
}

}  // namespace canopy::world
