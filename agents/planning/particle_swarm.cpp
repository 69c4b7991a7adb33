#include "agents/planning/particle_swarm.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

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

bool ParticleSwarm::updateNeighbourhoods(std::size_t n, std::size_t dim, int neighbours,
                                         std::span<const double> swarm_best, double ftol) {
  const std::size_t k = static_cast<std::size_t>(
      std::clamp<long long>(neighbours, 0, static_cast<long long>((n - 1) / 2)));
  if (neighbourhood_cost_.size() != n)
    neighbourhood_cost_.assign(n, std::numeric_limits<double>::infinity());
  bool progress = false;
  for (std::size_t p = 0; p < n; ++p) {
    std::size_t best = n;  // none with a finite own best
    for (std::size_t j = 0; j <= 2 * k; ++j) {
      const std::size_t q = (p + n - k + j) % n;
      if (std::isfinite(own_best_cost_[q]) &&
          (best == n || own_best_cost_[q] < own_best_cost_[best] ||
           (own_best_cost_[q] == own_best_cost_[best] && q < best))) {
        best = q;
      }
    }
    const double previous = neighbourhood_cost_[p];
    const double now = best == n ? std::numeric_limits<double>::infinity() : own_best_cost_[best];
    if (std::isfinite(previous) && now < previous - ftol * (1.0 + std::abs(previous))) {
      progress = true;
    }
    neighbourhood_cost_[p] = now;
    const double* from = best == n ? swarm_best.data() : own_best_.data() + best * dim;
    std::copy(from, from + dim, swarm_best_.begin() + p * dim);
  }
  return progress;
}

SwarmResult ParticleSwarm::minimise(const BatchCost& cost, std::span<const double> lo,
                                    std::span<const double> hi, const SwarmOptions& options,
                                    RandomStream& rng, std::span<const double> warm_start,
                                    const SwarmBlocks* blocks) {
  const std::size_t dim = lo.size();
  const std::size_t n = static_cast<std::size_t>(std::max(1, options.particles));
  if (hi.size() != dim || dim == 0 || warm_start.size() % dim != 0 || warm_start.size() > n * dim) {
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
    x_[d] = wrapPeriodic(warm_start[d], lo[d % dim], hi[d % dim]);
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
  // The swarm's best repeated over particles [first, last) (the kernels read it per particle).
  auto repeatSwarmBest = [&](std::size_t first, std::size_t last) {
    for (std::size_t p = first; p < last; ++p) {
      std::copy(result.best.begin(), result.best.end(), swarm_best_.begin() + p * dim);
    }
  };
  repeatSwarmBest(0, n);
  random_ = lanes::RandomLanes::from(rng);  // r1, r2 of every iteration
  const SwarmMove move{count,        options.inertia,  options.c1,         options.c2,
                       &random_,     own_best_.data(), swarm_best_.data(), lo_.data(),
                       hi_.data(),   width_.data(),    x_.data(),          v_.data(),
                       moved_.data()};
  const InstructionSet kernels = instructionSet();
  const bool ring = options.topology == SwarmTopology::ring;
  const int restart_after = options.restart_after;
  if (ring) {
    neighbourhood_cost_.clear();  // a new swarm: no previous neighbourhood bests
    updateNeighbourhoods(n, dim, options.neighbours, result.best);
  }
  since_improved_.assign(n, 0);
  const bool in_blocks = blocks != nullptr && blocks->count > 1 && blocks->width % 4 == 0 &&
                         blocks->width * blocks->count >= n && !ring && restart_after <= 0;
  if (in_blocks) {
    block_random_.resize(blocks->count);
    improved_.assign(n, 0);
  }
  bool best_moved = false;  // blocks: the swarm's best changed since swarm_best_ was filled
  // Particle p's own best after its evaluation; true when it improved.
  auto keepOwnBest = [&](std::size_t p) {
    if (!(cost_[p] < own_best_cost_[p])) {
      ++since_improved_[p];
      return false;
    }
    since_improved_[p] = 0;
    own_best_cost_[p] = cost_[p];
    std::copy(x_.begin() + p * dim, x_.begin() + (p + 1) * dim, own_best_.begin() + p * dim);
    return true;
  };
  // Particle p, which improved its own best, as the swarm's best when it beats it.
  auto offerAsBest = [&](std::size_t p) {
    if (!(cost_[p] < result.best_cost)) return false;
    result.best_cost = cost_[p];
    std::copy(x_.begin() + p * dim, x_.begin() + (p + 1) * dim, result.best.begin());
    return true;
  };
  while (result.iterations < options.max_iterations) {
    const double previous = result.best_cost;
    bool improved = false;
    if (in_blocks) {
      // Block b's streams start where block b − 1's draws end: two draws per four coordinates.
      const std::size_t width = blocks->width;
      for (std::size_t b = 0; b < blocks->count; ++b) {
        block_random_[b] = b == 0 ? random_ : block_random_[b - 1];
        if (b > 0) lanes::advance(block_random_[b], 2 * ((width * dim + 3) / 4));
      }
      // Each block: the swarm's best repeated over its particles when it moved, then its
      // particles moved with its streams, evaluated, and their own bests kept.
      blocks->run(blocks->count, [&](std::size_t b) {
        const std::size_t first = std::min(b * width, n), last = std::min(first + width, n);
        if (first == last) return;
        if (best_moved) repeatSwarmBest(first, last);
        const std::size_t from = first * dim, part_count = (last - first) * dim;
        SwarmMove part = move;
        part.count = part_count;
        part.random = &block_random_[b];
        part.own_best = own_best_.data() + from;
        part.swarm_best = swarm_best_.data() + from;
        part.lo = lo_.data() + from;
        part.hi = hi_.data() + from;
        part.width = width_.data() + from;
        part.x = x_.data() + from;
        part.v = v_.data() + from;
        part.moved = moved_.data() + from;
        moveParticles(part, kernels);
        blocks->cost(b, std::span<const double>(x_).subspan(from, part_count),
                     std::span<double>(cost_).subspan(first, last - first));
        for (std::size_t p = first; p < last; ++p) improved_[p] = keepOwnBest(p);
      });
      // The streams go on from where the last block with particles stopped drawing.
      random_ = block_random_[(n + width - 1) / width - 1];
      best_moved = false;
      for (std::size_t p = 0; p < n; ++p) {  // in order: the first of equal costs is the best
        if (improved_[p] && offerAsBest(p)) improved = true;
      }
    } else {
      moveParticles(move, kernels);
      cost(x_, cost_);
      for (std::size_t p = 0; p < n; ++p) {
        if (keepOwnBest(p) && offerAsBest(p)) improved = true;
      }
    }
    result.evaluations += static_cast<long long>(n);
    ++result.iterations;

    if (restart_after > 0) {
      for (std::size_t p = 0; p < n; ++p) {
        if (since_improved_[p] < restart_after || own_best_cost_[p] == result.best_cost) continue;
        for (std::size_t d = 0; d < dim; ++d) {
          const double range = hi[d] - lo[d];
          x_[p * dim + d] = rng.uniform(lo[d], hi[d]);
          v_[p * dim + d] = kInitialVelocityFraction * rng.uniform(-range, range);
        }
        // Its own best forgotten: it starts at the new position, replaced by the next evaluation.
        std::copy(x_.begin() + p * dim, x_.begin() + (p + 1) * dim, own_best_.begin() + p * dim);
        own_best_cost_[p] = std::numeric_limits<double>::infinity();
        since_improved_[p] = 0;
      }
    }
    if (ring) {
      // Stall: no neighbourhood best improved by ftol·(1 + |previous|) (a forgotten best that
      // is replaced by a worse one is no progress).
      stalls = updateNeighbourhoods(n, dim, options.neighbours, result.best, options.ftol)
                   ? 0
                   : stalls + 1;
    } else {
      if (in_blocks) {
        best_moved = best_moved || improved;  // each block repeats it over its own particles
      } else if (improved) {
        repeatSwarmBest(0, n);
      }
      // Stall: |best_k − best_{k−1}| < ftol·(1 + |best_{k−1}|).
      stalls = std::abs(result.best_cost - previous) < options.ftol * (1.0 + std::abs(previous))
                   ? stalls + 1
                   : 0;
    }
    if (stalls >= options.stall_iterations) {
      result.stalled = true;
      break;
    }
  }
  return result;
}

}  // namespace canopy::agents::planning
