#include "agents/planning/particle_swarm.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <mutex>
#include <numbers>
#include <vector>

#include "core/task_pool.h"

namespace canopy::agents::planning {
namespace {

// Calls f on every particle of the batch.
template <typename F>
BatchCost batchOf(std::size_t dim, F f) {
  return [dim, f](std::span<const double> x, std::span<double> costs) {
    for (std::size_t p = 0; p < costs.size(); ++p) costs[p] = f(x.subspan(p * dim, dim));
  };
}

double sphere(std::span<const double> x) {
  double s = 0;
  for (const double v : x) s += v * v;
  return s;
}

double rosenbrock(std::span<const double> x) {
  double s = 0;
  for (std::size_t i = 0; i + 1 < x.size(); ++i) {
    s += 100 * std::pow(x[i + 1] - x[i] * x[i], 2) + std::pow(1 - x[i], 2);
  }
  return s;
}

// Wrapped distance on the circle [0, 1): the minimum at 0.98 has half its basin across the bound.
double acrossBoundary(std::span<const double> x) {
  const double centre[] = {0.98, 0.01};
  double s = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double d = std::remainder(x[i] - centre[i], 1.0);  // in [−0.5, 0.5]
    s += d * d;
  }
  return s;
}

SwarmOptions precise(int particles, int max_iterations) {
  SwarmOptions o;  // the planner's w, c1, c2; a tight stall test so the swarm runs to precision
  o.particles = particles;
  o.ftol = 1e-15;
  o.stall_iterations = 100;
  o.max_iterations = max_iterations;
  return o;
}

TEST(ParticleSwarm, WrapsPeriodicallyIntoTheClosedBox) {
  EXPECT_DOUBLE_EQ(wrapPeriodic(0.25, 0, 1), 0.25);
  EXPECT_DOUBLE_EQ(wrapPeriodic(1.0, 0, 1), 1.0);  // the bound itself stays (speed = v_max)
  EXPECT_DOUBLE_EQ(wrapPeriodic(1.25, 0, 1), 0.25);
  EXPECT_DOUBLE_EQ(wrapPeriodic(3.5, 0, 1), 0.5);
  EXPECT_DOUBLE_EQ(wrapPeriodic(-0.25, 0, 1), 0.75);
  EXPECT_DOUBLE_EQ(wrapPeriodic(-2.5, -1, 1), 1.0 - 1.5);
}

TEST(ParticleSwarm, FindsTheMinimumOfTheSphere) {
  const std::vector<double> lo(5, -5.0), hi(5, 5.0);
  ParticleSwarm swarm;
  RandomStream rng(1, "test");
  const SwarmResult r = swarm.minimise(batchOf(5, sphere), lo, hi, precise(50, 3000), rng);
  for (const double v : r.best) EXPECT_NEAR(v, 0.0, 1e-4);
  EXPECT_LT(r.best_cost, 1e-8);
  EXPECT_EQ(r.evaluations, 50LL * (r.iterations + 1));
}

TEST(ParticleSwarm, FindsTheMinimumOfRosenbrockInTwoToFourDimensions) {
  for (const int dim : {2, 3, 4}) {
    const std::vector<double> lo(dim, -2.0), hi(dim, 2.0);
    ParticleSwarm swarm;
    RandomStream rng(3, "test", dim);
    const SwarmResult r =
        swarm.minimise(batchOf(dim, rosenbrock), lo, hi, precise(40 * dim, 20000), rng);
    for (const double v : r.best) EXPECT_NEAR(v, 1.0, 1e-3) << "dimension " << dim;
    EXPECT_LT(r.best_cost, 1e-6) << "dimension " << dim;
  }
}

TEST(ParticleSwarm, FindsAMinimumAcrossThePeriodicBoundary) {
  const std::vector<double> lo(2, 0.0), hi(2, 1.0);
  ParticleSwarm swarm;
  RandomStream rng(5, "test");
  const SwarmResult r = swarm.minimise(batchOf(2, acrossBoundary), lo, hi, precise(30, 3000), rng);
  EXPECT_NEAR(std::remainder(r.best[0] - 0.98, 1.0), 0.0, 1e-5);
  EXPECT_NEAR(std::remainder(r.best[1] - 0.01, 1.0), 0.0, 1e-5);
  for (const double v : r.best) {
    EXPECT_GE(v, 0.0);
    EXPECT_LE(v, 1.0);
  }
}

TEST(ParticleSwarm, IdenticalSeedsGiveBitwiseIdenticalResults) {
  const std::vector<double> lo(3, -2.0), hi(3, 2.0);
  const SwarmOptions options = SwarmOptions::from(PsoConfig{}, 2);  // 40 particles, defaults
  ParticleSwarm a, b;
  RandomStream rng_a(11, "pso", 1), rng_b(11, "pso", 1), rng_c(12, "pso", 1);
  const SwarmResult ra = a.minimise(batchOf(3, rosenbrock), lo, hi, options, rng_a);
  const SwarmResult rb = b.minimise(batchOf(3, rosenbrock), lo, hi, options, rng_b);
  EXPECT_EQ(ra.best, rb.best);  // exact equality of every double
  EXPECT_EQ(ra.best_cost, rb.best_cost);
  EXPECT_EQ(ra.iterations, rb.iterations);
  // The same object reused (buffers kept) gives the same answer too; another seed does not.
  RandomStream rng_a2(11, "pso", 1);
  EXPECT_EQ(a.minimise(batchOf(3, rosenbrock), lo, hi, options, rng_a2).best, ra.best);
  EXPECT_NE(a.minimise(batchOf(3, rosenbrock), lo, hi, options, rng_c).best, ra.best);
}

// SwarmBlocks (a swarm shared out over a pool): each block draws its r1, r2 from streams advanced
// past the blocks before it, so the search is the whole swarm's, bit for bit, whatever order the
// blocks run in and on whichever thread; swarms whose size is not a multiple of the width, and
// blocks left empty, included.
TEST(ParticleSwarm, BlocksMoveAndEvaluateAsTheWholeSwarmBitForBit) {
  struct Case {
    int particles;
    std::size_t dim, blocks;
  };
  TaskPool pool(2);
  for (const Case c :
       {Case{40, 3, 2}, Case{37, 5, 2}, Case{41, 10, 3}, Case{9, 4, 4}, Case{100, 10, 2}}) {
    const std::vector<double> lo(c.dim, -2.0), hi(c.dim, 2.0);
    SwarmOptions options = precise(c.particles, 300);
    options.ftol = 1e-9;
    options.stall_iterations = 30;
    RandomStream whole_rng(5, "pso", c.dim), blocks_rng(5, "pso", c.dim);
    ParticleSwarm whole, in_blocks;
    const SwarmResult expected =
        whole.minimise(batchOf(c.dim, rosenbrock), lo, hi, options, whole_rng);

    const std::size_t n = static_cast<std::size_t>(c.particles);
    SwarmBlocks blocks;
    blocks.count = c.blocks;
    blocks.width = 4 * ((n + 4 * c.blocks - 1) / (4 * c.blocks));
    int calls = 0;
    blocks.run = [&](std::size_t count, const std::function<void(std::size_t)>& task) {
      if (++calls % 2 == 0) {
        pool.run(count, task);
        return;
      }
      for (std::size_t b = count; b-- > 0;) task(b);  // last block first
    };
    long long evaluated = 0;
    std::mutex mutex;
    blocks.cost = [&](std::size_t b, std::span<const double> x, std::span<double> costs) {
      ASSERT_EQ(x.size(), costs.size() * c.dim);
      ASSERT_LE(b * blocks.width + costs.size(), n);
      for (std::size_t p = 0; p < costs.size(); ++p)
        costs[p] = rosenbrock(x.subspan(p * c.dim, c.dim));
      const std::lock_guard lock(mutex);
      evaluated += static_cast<long long>(costs.size());
    };
    const SwarmResult got =
        in_blocks.minimise(batchOf(c.dim, rosenbrock), lo, hi, options, blocks_rng, {}, &blocks);
    EXPECT_EQ(got.best, expected.best) << c.particles << " particles, " << c.blocks << " blocks";
    EXPECT_EQ(got.best_cost, expected.best_cost);
    EXPECT_EQ(got.iterations, expected.iterations);
    EXPECT_EQ(got.evaluations, expected.evaluations);
    EXPECT_EQ(calls, got.iterations);  // every iteration after the first batch ran in blocks
    EXPECT_EQ(evaluated, static_cast<long long>(got.iterations) * c.particles);
    EXPECT_GT(got.iterations, 10);
  }
}

TEST(ParticleSwarm, StopsOnStallOrCapAndEvaluatesTheWholeSwarmPerCall) {
  const std::vector<double> lo(2, -1.0), hi(2, 1.0);
  SwarmOptions options;
  options.particles = 16;
  int calls = 0;
  const BatchCost flat = [&calls](std::span<const double> x, std::span<double> costs) {
    ++calls;
    EXPECT_EQ(costs.size(), 16u);
    EXPECT_EQ(x.size(), 32u);
    for (double& c : costs) c = 1.0;
  };
  ParticleSwarm swarm;
  RandomStream rng(2, "test");
  // A flat cost never changes the best: it stalls after exactly stall_iterations iterations.
  SwarmResult r = swarm.minimise(flat, lo, hi, options, rng);
  EXPECT_TRUE(r.stalled);
  EXPECT_EQ(r.iterations, options.stall_iterations);
  EXPECT_EQ(calls, options.stall_iterations + 1);
  options.max_iterations = 7;
  r = swarm.minimise(flat, lo, hi, options, rng);
  EXPECT_FALSE(r.stalled);
  EXPECT_EQ(r.iterations, 7);
}

TEST(ParticleSwarm, WarmStartIsParticleZero) {
  const std::vector<double> lo(2, -5.0), hi(2, 5.0);
  const std::vector<double> warm{0.0, 0.0};  // the minimum of the sphere
  SwarmOptions options;
  options.particles = 10;
  options.max_iterations = 0;  // only the initial swarm
  ParticleSwarm swarm;
  RandomStream rng(4, "test");
  const SwarmResult r = swarm.minimise(batchOf(2, sphere), lo, hi, options, rng, warm);
  EXPECT_EQ(r.best, warm);
  EXPECT_EQ(r.best_cost, 0.0);
}

TEST(ParticleSwarm, SeveralWarmStartsTakeTheFirstParticles) {
  const std::vector<double> lo(2, -5.0), hi(2, 5.0);
  const std::vector<double> warm{1.0, 2.0, -3.0, 4.0};  // two starts
  SwarmOptions options;
  options.particles = 10;
  options.max_iterations = 0;
  ParticleSwarm swarm;
  RandomStream rng(4, "test");
  std::vector<double> seen;
  const BatchCost record = [&seen](std::span<const double> x, std::span<double> costs) {
    seen.assign(x.begin(), x.end());
    for (double& c : costs) c = 1.0;
  };
  swarm.minimise(record, lo, hi, options, rng, warm);
  ASSERT_EQ(seen.size(), 20u);
  EXPECT_EQ(std::vector<double>(seen.begin(), seen.begin() + 4), warm);
  // The other particles are the draws a swarm without warm starts makes.
  RandomStream again(4, "test");
  std::vector<double> cold;
  const BatchCost record_cold = [&cold](std::span<const double> x, std::span<double> costs) {
    cold.assign(x.begin(), x.end());
    for (double& c : costs) c = 1.0;
  };
  swarm.minimise(record_cold, lo, hi, options, again);
  EXPECT_EQ(std::vector<double>(seen.begin() + 4, seen.end()),
            std::vector<double>(cold.begin() + 4, cold.end()));
}

SwarmOptions ringWithRestarts(int particles, int max_iterations) {
  SwarmOptions o = precise(particles, max_iterations);
  o.topology = SwarmTopology::ring;
  o.neighbours = 1;
  o.restart_after = 25;
  return o;
}

TEST(ParticleSwarm, RingWithRestartsFindsTheMinimaOfTheSphereAndRosenbrock) {
  {
    const std::vector<double> lo(5, -5.0), hi(5, 5.0);
    ParticleSwarm swarm;
    RandomStream rng(1, "test");
    const SwarmResult r =
        swarm.minimise(batchOf(5, sphere), lo, hi, ringWithRestarts(50, 3000), rng);
    for (const double v : r.best) EXPECT_NEAR(v, 0.0, 1e-4);
    EXPECT_LT(r.best_cost, 1e-8);
  }
  const std::vector<double> lo(3, -2.0), hi(3, 2.0);
  ParticleSwarm swarm;
  RandomStream rng(3, "test");
  const SwarmResult r =
      swarm.minimise(batchOf(3, rosenbrock), lo, hi, ringWithRestarts(120, 20000), rng);
  for (const double v : r.best) EXPECT_NEAR(v, 1.0, 1e-3);
}

TEST(ParticleSwarm, RingReturnsTheLowestCostEverEvaluatedAndIsDeterministic) {
  // Restarts forget particles' own bests; the swarm's best must still be the minimum over every
  // evaluation made (recorded independently by the cost).
  const std::vector<double> lo(4, -3.0), hi(4, 3.0);
  const SwarmOptions options = ringWithRestarts(20, 400);
  double lowest = std::numeric_limits<double>::infinity();
  long long evaluations = 0;
  const BatchCost rastrigin = [&](std::span<const double> x, std::span<double> costs) {
    for (std::size_t p = 0; p < costs.size(); ++p) {
      double s = 40.0;
      for (std::size_t d = 0; d < 4; ++d) {
        const double v = x[p * 4 + d];
        s += v * v - 10.0 * std::cos(2.0 * std::numbers::pi * v);
      }
      costs[p] = s;
      lowest = std::min(lowest, s);
      ++evaluations;
    }
  };
  ParticleSwarm swarm;
  RandomStream rng(8, "test");
  const SwarmResult r = swarm.minimise(rastrigin, lo, hi, options, rng);
  EXPECT_EQ(r.best_cost, lowest);
  EXPECT_EQ(r.evaluations, evaluations);
  RandomStream rng2(8, "test");
  const SwarmResult again = swarm.minimise(rastrigin, lo, hi, options, rng2);
  EXPECT_EQ(again.best, r.best);
  EXPECT_EQ(again.iterations, r.iterations);
}

TEST(ParticleSwarm, RingStallsWhenNoNeighbourhoodImproves) {
  const std::vector<double> lo(2, -1.0), hi(2, 1.0);
  SwarmOptions options;
  options.particles = 16;
  options.topology = SwarmTopology::ring;
  const BatchCost flat = [](std::span<const double>, std::span<double> costs) {
    for (double& c : costs) c = 1.0;
  };
  ParticleSwarm swarm;
  RandomStream rng(2, "test");
  const SwarmResult r = swarm.minimise(flat, lo, hi, options, rng);
  EXPECT_TRUE(r.stalled);
  EXPECT_EQ(r.iterations, options.stall_iterations);
}

}  // namespace
}  // namespace canopy::agents::planning
