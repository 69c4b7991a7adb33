#include "agents/planning/particle_swarm.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace canopy::agents::planning {
namespace {
/// The shortest periodic displacement d mod width, in [−width/2, width/2]. Both ends of a swarm
/// displacement lie in the box, so |d| ≤ width and one shift suffices.
double shortestDisplacement(double d, double width) {
  if (d > 0.5 * width) return d - width;
  if (d < -0.5 * width) return d + width;
  return d;
}

}  // namespace

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

double wrapPeriodic(double x, double lo, double hi) {
  const double width = hi - lo;
  if (!(width > 0.0)) return lo;
  if (x > hi) return lo + std::fmod(x - hi, width);
  if (x < lo) return hi - std::fmod(lo - x, width);
  return x;
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
  while (result.iterations < options.max_iterations) {
    for (std::size_t p = 0; p < n; ++p) {
      for (std::size_t d = 0; d < dim; ++d) {
        const std::size_t k = p * dim + d;
        const double r1 = rng.uniform();
        const double r2 = rng.uniform();
        const double width = hi[d] - lo[d];
        v_[k] = options.inertia * v_[k] +
                options.c1 * r1 * shortestDisplacement(own_best_[k] - x_[k], width) +
                options.c2 * r2 * shortestDisplacement(result.best[d] - x_[k], width);
        x_[k] = wrapPeriodic(x_[k] + v_[k], lo[d], hi[d]);
      }
    }
    cost(x_, cost_);
    result.evaluations += static_cast<long long>(n);
    ++result.iterations;

    const double previous = result.best_cost;
    for (std::size_t p = 0; p < n; ++p) {
      if (!(cost_[p] < own_best_cost_[p])) continue;
      own_best_cost_[p] = cost_[p];
      std::copy(x_.begin() + p * dim, x_.begin() + (p + 1) * dim, own_best_.begin() + p * dim);
      if (cost_[p] < result.best_cost) {
        result.best_cost = cost_[p];
        std::copy(x_.begin() + p * dim, x_.begin() + (p + 1) * dim, result.best.begin());
      }
    }
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
