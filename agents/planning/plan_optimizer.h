#pragma once
// NBO for a set of UAVs: the particle swarm over their speeds and headings, the cost over the
// joint plan with every other UAV held to a given plan (algorithms.md §6).
#include <span>
#include <vector>

#include "agents/config.h"
#include "agents/planning/nominal_cost.h"
#include "agents/planning/particle_swarm.h"
#include "agents/planning/plan.h"
#include "core/random.h"

namespace canopy::agents::planning {

struct PlanSearch {
  std::vector<Plan> plans;    // one per free UAV, in the order given; each carries `cost`
  double cost = 0.0;          // J of the best joint plan found
  int iterations = 0;         // swarm iterations
  long long evaluations = 0;  // cost evaluations
};

/// The swarm's social structure beyond the paper's global best (particle_swarm.h).
struct SwarmShape {
  SwarmTopology topology = SwarmTopology::global_best;
  int neighbours = 1;     // ring: particles on each side
  int restart_after = 0;  // > 0: restart a particle after this many iterations without progress
  int particles_per_step = 0;  // > 0: instead of pso.particles_per_step
  int max_iterations = 0;      // > 0: instead of pso.max_iterations
};

/// Decision variables, per free UAV f and step m (agent-major): x[2(f·H + m)] = speed ∈ [0,
/// v_max_f] (m/s), x[2(f·H + m) + 1] = heading ∈ [0, 2π] (rad); a_{f,m} = speed · (cos heading, sin
/// heading). Height (issue 53): then, for each free UAV whose altitude is free (altitudeFree), in
/// order, its H climb rates x[2·n_free·H + c·H + m] ∈ [−climb_rate, climb_rate] (m/s), returned as
/// its plan's `climbs`; without such a UAV the vector is the paper's. Keeps its buffers between
/// calls; one instance per thread.
class PlanOptimizer {
 public:
  /// free_agents: the UAVs to optimise (SMA: the planning agent; Dec-POMDP: all). assumed: one
  /// plan per UAV, used for the others. warm_start: empty, or k joint starts of one plan per free
  /// UAV each (k·free_agents.size() plans, start-major; the first is the previous plan already
  /// shifted), given to particles 0 … k − 1 when pso.warm_start is on.
  PlanSearch optimise(const PlanningProblem& problem, const PsoConfig& pso,
                      std::span<const int> free_agents, std::span<const Plan> assumed,
                      std::span<const Plan> warm_start, RandomStream& rng,
                      const SwarmShape& shape = {});

 private:
  NominalCost cost_;
  ParticleSwarm swarm_;
  std::vector<double> lo_, hi_, warm_;
  std::vector<Vec2> actions_;        // m/s, the free UAVs' actions of one particle
  std::vector<Vec2> swarm_actions_;  // m/s, every particle's actions (particle-major)
  std::vector<double> swarm_climbs_;  // m/s, every particle's climb rates (particle-major)
};

}  // namespace canopy::agents::planning
