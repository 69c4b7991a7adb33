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
  TaskPool* const pool = shared_ == nullptr ? nullptr : shared_->pool;
  cost_.prepare(problem, free_agents, assumed, pool);
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
    const std::size_t n = costs.size();
    resizeDecoded(n, n_climbs);
    decode(positions, 0, n, n_moves, n_climbs);
    if (n_climbs == 0) {
      cost_.evaluate(swarm_actions_, costs);
      return;
    }
    cost_.evaluate(swarm_actions_, swarm_climbs_, costs);
  };
  // The same with the swarm's blocks side by side. Block b: particles [b·w, min((b + 1)·w, n)),
  // w = 4·⌈n / (4·blocks)⌉, so that the lanes group the candidates as one evaluate() over the
  // whole swarm does. Block b's particles (`positions` holds theirs only) are decoded into their
  // entries and evaluated on block b's copy of the prepared cost.
  const std::size_t n_particles = static_cast<std::size_t>(std::max(1, options.particles));
  const std::size_t width = 4 * ((n_particles + 4 * blocks - 1) / (4 * blocks));
  const auto evaluate_block = [this, n_moves, n_climbs, width](std::size_t b,
                                                               std::span<const double> positions,
                                                               std::span<double> costs) {
    const std::size_t first = b * width, last = first + costs.size();
    const std::size_t per_particle = actions_.size();
    decode(positions, first, last, n_moves, n_climbs);
    if (!copied_[b]) {  // cost_ is only read while the blocks run
      shared_->costs[b] = cost_;
      copied_[b] = 1;
    }
    const std::span<const Vec2> actions(swarm_actions_.data() + first * per_particle,
                                        (last - first) * per_particle);
    const std::span<const double> climbs =
        n_climbs == 0 ? std::span<const double>()
                      : std::span<const double>(swarm_climbs_.data() + first * n_climbs,
                                                (last - first) * n_climbs);
    shared_->costs[b].evaluate(actions, climbs, costs);
  };
  // The iterations move and evaluate each block on its own (SwarmBlocks); the first batch (the
  // initial swarm) is evaluated in the same blocks.
  SwarmBlocks swarm_blocks;
  swarm_blocks.count = blocks;
  swarm_blocks.width = width;
  swarm_blocks.run = [&](std::size_t count, const std::function<void(std::size_t)>& task) {
    pool->run(count, task);
    ++shared_batches_;
  };
  swarm_blocks.cost = evaluate_block;
  const std::size_t dim = lo_.size();
  const auto shared_batch = [&](std::span<const double> positions, std::span<double> costs) {
    const std::size_t n = costs.size();
    resizeDecoded(n, n_climbs);
    swarm_blocks.run(blocks, [&](std::size_t b) {
      const std::size_t first = std::min(b * width, n), last = std::min(first + width, n);
      if (first == last) return;
      evaluate_block(b, positions.subspan(first * dim, (last - first) * dim),
                     costs.subspan(first, last - first));
    });
  };
  // No more warm starts than particles (the first ones kept).
  warm_.resize(std::min(warm_.size(), n_particles * dim));
  const SwarmResult best =
      swarm_.minimise(shared ? BatchCost(shared_batch) : BatchCost(batch), lo_, hi_, options, rng,
                      warm_, shared ? &swarm_blocks : nullptr);

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

void PlanOptimizer::resizeDecoded(std::size_t n, std::size_t n_climbs) {
  swarm_actions_.resize(n * actions_.size());
  swarm_climbs_.resize(n * n_climbs);
}

void PlanOptimizer::decode(std::span<const double> positions, std::size_t first, std::size_t last,
                           std::size_t n_moves, std::size_t n_climbs) {
  const std::size_t per_particle = actions_.size();
  const std::size_t dim = n_moves + n_climbs;
  const std::span<Vec2> actions =
      std::span<Vec2>(swarm_actions_).subspan(first * per_particle, (last - first) * per_particle);
  if (n_climbs == 0) {
    decodeActions(positions, actions);
    return;
  }
  // Each particle's speeds and headings, then its climb rates (read as they are).
  for (std::size_t k = 0; k < last - first; ++k) {
    decodeActions(positions.subspan(k * dim, n_moves),
                  actions.subspan(k * per_particle, per_particle));
    std::copy_n(positions.begin() + static_cast<std::ptrdiff_t>(k * dim + n_moves), n_climbs,
                swarm_climbs_.begin() + static_cast<std::ptrdiff_t>((first + k) * n_climbs));
  }
}

}  // namespace canopy::agents::planning
