#include "agents/planning/plan_optimizer.h"

#include <algorithm>
#include <cmath>

#include "agents/planning/swarm_kernels.h"
#include "core/angles.h"

namespace canopy::agents::planning {

PlanSearch PlanOptimizer::optimise(const PlanningProblem& problem, const PsoConfig& pso,
                                   std::span<const int> free_agents, std::span<const Plan> assumed,
                                   std::span<const Plan> warm_start, RandomStream& rng,
                                   const SwarmShape& shape) {
  const int H = problem.settings.horizon;
  const std::size_t n_free = free_agents.size();
  cost_.prepare(problem, free_agents, assumed);
  actions_.resize(n_free * H);
  lo_.assign(2 * n_free * H, 0.0);
  hi_.resize(lo_.size());
  for (std::size_t f = 0; f < n_free; ++f) {
    for (int m = 0; m < H; ++m) {
      const std::size_t k = 2 * (f * H + m);
      hi_[k] = problem.uavs[free_agents[f]].v_max;
      hi_[k + 1] = kTwoPi;
    }
  }
  warm_.clear();
  if (pso.warm_start && n_free > 0 && !warm_start.empty() && warm_start.size() % n_free == 0) {
    for (std::size_t k = 0; k < warm_start.size(); ++k) {
      const std::size_t f = k % n_free;
      for (int m = 0; m < H; ++m) {
        const Vec2 a = warm_start[k].action(m);
        const double speed = a.norm();
        warm_.push_back(std::min(speed, problem.uavs[free_agents[f]].v_max));
        warm_.push_back(speed > 0.0 ? wrapAnglePositive(std::atan2(a.y(), a.x())) : 0.0);
      }
    }
  }

  // The whole swarm decoded at once (swarm_kernels.h), then evaluated four particles at a time.
  const BatchCost batch = [this](std::span<const double> positions, std::span<double> costs) {
    const std::size_t per_particle = actions_.size();
    swarm_actions_.resize(costs.size() * per_particle);
    decodeActions(positions, swarm_actions_);
    cost_.evaluate(swarm_actions_, costs);
  };
  SwarmOptions options = SwarmOptions::from(pso, H);
  options.topology = shape.topology;
  options.neighbours = shape.neighbours;
  options.restart_after = shape.restart_after;
  if (shape.particles_per_step > 0) options.particles = shape.particles_per_step * H;
  if (shape.max_iterations > 0) options.max_iterations = shape.max_iterations;
  // No more warm starts than particles (the first ones kept).
  warm_.resize(std::min(warm_.size(),
                        static_cast<std::size_t>(std::max(1, options.particles)) * lo_.size()));
  const SwarmResult best = swarm_.minimise(batch, lo_, hi_, options, rng, warm_);

  decodeActions(best.best, actions_);
  PlanSearch search;
  search.cost = best.best_cost;
  search.iterations = best.iterations;
  search.evaluations = best.evaluations;
  search.plans.resize(n_free);
  for (std::size_t f = 0; f < n_free; ++f) {
    search.plans[f].velocities.assign(actions_.begin() + f * H, actions_.begin() + (f + 1) * H);
    search.plans[f].cost = best.best_cost;
  }
  return search;
}

}  // namespace canopy::agents::planning
