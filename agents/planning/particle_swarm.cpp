#include "agents/planning/particle_swarm.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace canopy::agents::planning {
SwarmOptions SwarmOptions::from(const PsoConfig& config, int horizon) {
  SwarmOptions o;
  o.particles = config.particles_per_step * horizon;
  o.inertia = config.inertia;
  o.c1 = config.c1;
  o.c2 = config.c2;
  o.ftol = config.ftol;
  o.stall_iterations = config.stall_iterations;
  o.max_iterations = config.max_iterations;
  return o;
}

SwarmResult ParticleSwarm::minimise(const BatchCost& cost, std::span<const double> lo,
                                    std::span<const double> hi, const SwarmOptions& options,
                                    RandomStream& rng, std::span<const double> warm_start) {
  const std::size_t dim = lo.size();
  const std::size_t n = static_cast<std::size_t>(std::max(1, options.particles));
  if (hi.size() != dim || (!warm_start.empty() && warm_start.size() != dim)) {
    std::fprintf(stderr, "ParticleSwarm::minimise: bounds of size %zu and %zu, warm start %zu\n",
                 dim, hi.size(), warm_start.size());
    std::abort();
  }
  x_.resize(n * dim);
  v_.resize(n * dim);
  cost_.resize(n);
  for (std::size_t p = 0; p < n; ++p) {
    for (std::size_t d = 0; d < dim; ++d) {
      const double range = hi[d] - lo[d];
      x_[p * dim + d] = rng.uniform(lo[d], hi[d]);
      v_[p * dim + d] = kInitialVelocityFraction * rng.uniform(-range, range);
    }
  }
  for (std::size_t d = 0; d < warm_start.size(); ++d) {
    x_[d] = wrapPeriodic(warm_start[d], lo[d], hi[d]);
  }

  SwarmResult result;
  cost(x_, cost_);
  result.evaluations = static_cast<long long>(n);
  own_best_ = x_;
  own_best_cost_ = cost_;
  std::size_t best = 0;
  for (std::size_t p = 1; p < n; ++p) {
    if (cost_[p] < cost_[best]) best = p;
  }
  result.best.assign(x_.begin() + best * dim, x_.begin() + (best + 1) * dim);
  result.best_cost = cost_[best];

  int stalls = 0;
  const std::size_t count = n * dim;
  lo_.resize(count);
  hi_.resize(count);
  width_.resize(count);
  swarm_best_.resize(count);
  moved_.resize(count);
  for (std::size_t i = 0; i < count; ++i) {  // the box, repeated per particle
    lo_[i] = lo[i % dim];
    hi_[i] = hi[i % dim];
    width_[i] = hi_[i] - lo_[i];
  }
  auto repeatSwarmBest = [&] {
    for (std::size_t p = 0; p < n; ++p) {
      std::copy(result.best.begin(), result.best.end(), swarm_best_.begin() + p * dim);
    }
  };
  repeatSwarmBest();
  random_ = lanes::RandomLanes::from(rng);  // r1, r2 of every iteration
  const SwarmMove move{count,        options.inertia,  options.c1,         options.c2,
                       &random_,     own_best_.data(), swarm_best_.data(), lo_.data(),
                       hi_.data(),   width_.data(),    x_.data(),          v_.data(),
                       moved_.data()};
  const InstructionSet kernels = instructionSet();
  while (result.iterations < options.max_iterations) {
    moveParticles(move, kernels);
    cost(x_, cost_);
    result.evaluations += static_cast<long long>(n);
    ++result.iterations;

    const double previous = result.best_cost;
    bool improved = false;
    for (std::size_t p = 0; p < n; ++p) {
      if (!(cost_[p] < own_best_cost_[p])) continue;
      own_best_cost_[p] = cost_[p];
      std::copy(x_.begin() + p * dim, x_.begin() + (p + 1) * dim, own_best_.begin() + p * dim);
      if (cost_[p] < result.best_cost) {
        result.best_cost = cost_[p];
        std::copy(x_.begin() + p * dim, x_.begin() + (p + 1) * dim, result.best.begin());
        improved = true;
      }
    }
    if (improved) repeatSwarmBest();
    // Stall: |best_k − best_{k−1}| < ftol·(1 + |best_{k−1}|).
    stalls = std::abs(result.best_cost - previous) < options.ftol * (1.0 + std::abs(previous))
                 ? stalls + 1
                 : 0;
    if (stalls >= options.stall_iterations) {
      result.stalled = true;
      break;
    }
  }
  return result;
}

}  // namespace canopy::agents::planning
