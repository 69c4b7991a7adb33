#include "agents/planning/plan_optimizer.h"

#include <algorithm>
#include <cmath>

#include "agents/planning/altitude_choice.h"
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
  // Height: the climb rates of the free UAVs whose altitude is free follow the speeds and
  // headings, H each in [−climb_rate, climb_rate] (none: the decision vector is the paper's).
  const std::size_t n_moves = 2 * n_free * H;
  const std::size_t n_climbs = static_cast<std::size_t>(cost_.climbCount());
  std::vector<std::size_t> climbing;  // the free UAVs (f) whose climbs are searched, in order
  for (std::size_t f = 0; f < n_free; ++f)
    if (altitudeFree(problem.uavs[free_agents[f]])) climbing.push_back(f);
  lo_.assign(n_moves + n_climbs, 0.0);
  hi_.resize(lo_.size());
  for (std::size_t f = 0; f < n_free; ++f) {
    for (int m = 0; m < H; ++m) {
      const std::size_t k = 2 * (f * H + m);
      hi_[k] = problem.uavs[free_agents[f]].v_max;
      hi_[k + 1] = kTwoPi;
    }
  }
  for (std::size_t c = 0; c < climbing.size(); ++c) {
    const double rate = problem.uavs[free_agents[climbing[c]]].climb_rate;
    for (int m = 0; m < H; ++m) {
      lo_[n_moves + c * H + m] = -rate;  // m/s
      hi_[n_moves + c * H + m] = rate;
    }
  }
  warm_.clear();
  if (pso.warm_start && n_free > 0 && !warm_start.empty() && warm_start.size() % n_free == 0) {
    for (std::size_t start = 0; start < warm_start.size(); start += n_free) {
      for (std::size_t f = 0; f < n_free; ++f) {
        for (int m = 0; m < H; ++m) {
          const Vec2 a = warm_start[start + f].action(m);
          const double speed = a.norm();
          warm_.push_back(std::min(speed, problem.uavs[free_agents[f]].v_max));
          warm_.push_back(speed > 0.0 ? wrapAnglePositive(std::atan2(a.y(), a.x())) : 0.0);
        }
      }
      for (const std::size_t f : climbing) {
        const double rate = problem.uavs[free_agents[f]].climb_rate;
        for (int m = 0; m < H; ++m)
          warm_.push_back(std::clamp(warm_start[start + f].climb(m), -rate, rate));
      }
    }
  }

  SwarmOptions options = SwarmOptions::from(pso, H);
  options.topology = shape.topology;
  options.neighbours = shape.neighbours;
  options.restart_after = shape.restart_after;
  if (shape.particles_per_step > 0) options.particles = shape.particles_per_step * H;
  if (shape.max_iterations > 0) options.max_iterations = shape.max_iterations;
  // Shared out when one batch is large enough (class comment); each block's copy of the prepared
  // cost is made by the block's own task at the search's first batch (the blocks only read cost_,
  // so they copy it side by side).
  TaskPool* const pool = shared_ == nullptr ? nullptr : shared_->pool;
  const std::size_t blocks = pool == nullptr ? 1 : static_cast<std::size_t>(pool->threads());
  const bool shared =
      blocks > 1 && static_cast<std::size_t>(std::max(1, options.particles)) *
                            problem.targets.size() >= kSharedWork;
  if (shared) {
    shared_->costs.resize(blocks);
    copied_.assign(blocks, 0);
  }
  // The whole swarm decoded at once (swarm_kernels.h), then evaluated four particles at a time.
  const auto batch = [this, n_moves, n_climbs](std::span<const double> positions,
                                                std::span<double> costs) {
    const std::size_t per_particle = actions_.size();
    swarm_actions_.resize(costs.size() * per_particle);
    if (n_climbs == 0) {
      decodeActions(positions, swarm_actions_);
      cost_.evaluate(swarm_actions_, costs);
      return;
    }
    decode(positions, costs.size(), n_moves, n_climbs);
    cost_.evaluate(swarm_actions_, swarm_climbs_, costs);
  };
  // The same with the swarm's blocks evaluated side by side. Block b: particles [b·w, min((b +
  // 1)·w, n)), w = 4·⌈n / (4·blocks)⌉, so that the lanes group the candidates as one evaluate()
  // over the whole swarm does.
  const auto shared_batch = [this, n_moves, n_climbs, blocks, pool](
                                std::span<const double> positions, std::span<double> costs) {
    const std::size_t n = costs.size(), per_particle = actions_.size();
    decode(positions, n, n_moves, n_climbs);
    const std::size_t width = 4 * ((n + 4 * blocks - 1) / (4 * blocks));
    std::vector<NominalCost>& copies = shared_->costs;
    pool->run(blocks, [&](std::size_t b) {
      const std::size_t first = std::min(b * width, n), last = std::min(first + width, n);
      if (first == last) return;
      if (!copied_[b]) {  // cost_ is only read while the blocks run
        copies[b] = cost_;
        copied_[b] = 1;
      }
      const std::span<const Vec2> actions(swarm_actions_.data() + first * per_particle,
                                          (last - first) * per_particle);
      const std::span<const double> climbs =
          n_climbs == 0 ? std::span<const double>()
                        : std::span<const double>(swarm_climbs_.data() + first * n_climbs,
                                                  (last - first) * n_climbs);
      copies[b].evaluate(actions, climbs, costs.subspan(first, last - first));
    });
    ++shared_batches_;
  };
  // No more warm starts than particles (the first ones kept).
  warm_.resize(std::min(warm_.size(),
                        static_cast<std::size_t>(std::max(1, options.particles)) * lo_.size()));
  const SwarmResult best = swarm_.minimise(
      shared ? BatchCost(shared_batch) : BatchCost(batch), lo_, hi_, options, rng, warm_);

  decodeActions(std::span<const double>(best.best).first(n_moves), actions_);
  PlanSearch search;
  search.cost = best.best_cost;
  search.iterations = best.iterations;
  search.evaluations = best.evaluations;
  search.plans.resize(n_free);
  for (std::size_t f = 0; f < n_free; ++f) {
    search.plans[f].velocities.assign(actions_.begin() + f * H, actions_.begin() + (f + 1) * H);
    search.plans[f].cost = best.best_cost;
  }
  for (std::size_t c = 0; c < climbing.size(); ++c) {
    const auto from = best.best.begin() + static_cast<std::ptrdiff_t>(n_moves + c * H);
    search.plans[climbing[c]].climbs.assign(from, from + H);
  }
  return search;
}

void PlanOptimizer::decode(std::span<const double> positions, std::size_t n, std::size_t n_moves,
                           std::size_t n_climbs) {
  const std::size_t per_particle = actions_.size();
  swarm_actions_.resize(n * per_particle);
  if (n_climbs == 0) {
    decodeActions(positions, swarm_actions_);
    return;
  }
  // Each particle's speeds and headings, then its climb rates (read as they are).
  swarm_climbs_.resize(n * n_climbs);
  const std::size_t dim = n_moves + n_climbs;
  for (std::size_t p = 0; p < n; ++p) {
    decodeActions(positions.subspan(p * dim, n_moves),
                  std::span<Vec2>(swarm_actions_).subspan(p * per_particle, per_particle));
    std::copy_n(positions.begin() + static_cast<std::ptrdiff_t>(p * dim + n_moves), n_climbs,
                swarm_climbs_.begin() + static_cast<std::ptrdiff_t>(p * n_climbs));
  }
}

}  // namespace canopy::agents::planning
