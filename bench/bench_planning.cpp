// NBO planning speed (algorithms.md §6). The reference Python SMA-NBO planner manages about 340
// cost evaluations per second with 3 UAVs, 4 targets and H = 5, and takes 10–80 s per planning
// call. Targets: one cost evaluation ≤ 2 µs; one SMA-NBO call for one agent ≤ 30 ms median; one
// Dec-POMDP call (2 UAVs, joint plan) ≤ 150 ms median.
//
//   build/<dir>/bench/bench_planning --benchmark_repetitions=10 --benchmark_report_aggregates_only
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "agents/occlusion_map.h"
#include "agents/planning/nominal_cost.h"
#include "agents/planning/plan_optimizer.h"
#include "agents/planning/team_planner.h"
#include "core/angles.h"
#include "core/random.h"

namespace canopy::agents::planning {
namespace {

constexpr int kHorizon = 5;

// A 100 × 100 m area with 50 trees, 4 moving targets and up to 3 UAVs spread over them, one
// target covered twice and one by nobody: a typical mid-trial state.
struct Scene {
  std::vector<TargetGaussian> targets;
  std::vector<UavState> uavs;
  OcclusionMap map;

  explicit Scene(int n_uavs) {
    RandomStream rng(2024, "bench", 0);
    std::vector<world::TreeDef> trees;
    for (int k = 0; k < 50; ++k) {
      trees.push_back(world::TreeDef::disc(Vec2(rng.uniform(0, 100), rng.uniform(0, 100)),
                                           rng.uniform(1.0, 3.0)));
    }
    map = OcclusionMap(std::move(trees));
    const Vec2 starts[] = {{30, 30}, {40, 35}, {70, 60}, {20, 80}};
    const Vec2 velocities[] = {{1.5, 0.5}, {-1, 1}, {0, -2}, {1, -1}};
    const double variances[] = {0.4, 0.8, 1.5, 6.0};
    for (int j = 0; j < 4; ++j) {
      TargetGaussian t;
      t.x << starts[j], velocities[j];
      t.P = variances[j] * Mat4::Identity();
      t.P(0, 2) = t.P(2, 0) = t.P(1, 3) = t.P(3, 1) = 0.3 * variances[j];
      targets.push_back(t);
    }
    const Vec2 positions[] = {{32, 28}, {68, 62}, {45, 40}};
    for (int i = 0; i < n_uavs; ++i) {
      UavState u;
      u.position = positions[i];
      u.yaw_mode = i == 1 ? world::YawMode::velocity : world::YawMode::fixed;
      u.footprint.size = i == 2 ? Vec2(30, 30) : Vec2(20, 20);
      uavs.push_back(u);
    }
  }
  PlanningProblem problem() const {
    PlannerConfig config;
    config.horizon = kHorizon;
    return {targets, uavs, &map, CostSettings::from(config, 1.0)};
  }
};

// Random joint plans to evaluate, drawn once: kBatches batches of kBatch candidates, one after the
// other (as the swarm hands them to the cost).
constexpr int kBatch = 100;  // the swarm's particles at H = 5 (particles_per_step · H)
constexpr int kBatches = 10;
std::vector<Vec2> randomActions(int n_uavs, int count) {
  RandomStream rng(7, "bench", 1);
  std::vector<Vec2> actions;
  for (int k = 0; k < count * n_uavs * kHorizon; ++k) {
    const double speed = rng.uniform(0, 5), heading = rng.uniform(0, kTwoPi);
    actions.push_back(speed * Vec2(std::cos(heading), std::sin(heading)));
  }
  return actions;
}

// Evaluates batches of kBatch candidates of `per_candidate` actions each; an item is one
// evaluation.
void evaluateBatches(benchmark::State& state, NominalCost& cost, int per_candidate) {
  const auto actions = randomActions(1, kBatches * kBatch * per_candidate / kHorizon);
  std::vector<double> costs(kBatch);
  const std::size_t batch_size = static_cast<std::size_t>(kBatch) * per_candidate;
  std::size_t k = 0;
  for (auto _ : state) {
    cost.evaluate(std::span<const Vec2>(actions).subspan((k++ % kBatches) * batch_size, batch_size),
                  costs);
    benchmark::DoNotOptimize(costs.data());
  }
  state.SetItemsProcessed(state.iterations() * kBatch);
}

// Evaluations of the joint plan of all three UAVs (the worst case: nothing held fixed).
void BM_CostEvaluationJoint3Uavs(benchmark::State& state) {
  const Scene scene(3);
  const std::vector<int> everyone{0, 1, 2};
  const std::vector<Plan> unused(3);
  NominalCost cost;
  cost.prepare(scene.problem(), everyone, unused);
  evaluateBatches(state, cost, 3 * kHorizon);
}
BENCHMARK(BM_CostEvaluationJoint3Uavs);

// Evaluations as SMA-NBO makes them: one UAV free, two held to their plans.
void BM_CostEvaluationSma3Uavs(benchmark::State& state) {
  const Scene scene(3);
  const std::vector<int> self{0};
  std::vector<Plan> others(3);
  const auto fixed = randomActions(3, 1);
  for (int i = 0; i < 3; ++i) {
    others[i].velocities.assign(fixed.begin() + i * kHorizon, fixed.begin() + (i + 1) * kHorizon);
  }
  NominalCost cost;
  cost.prepare(scene.problem(), self, others);
  evaluateBatches(state, cost, kHorizon);
}
BENCHMARK(BM_CostEvaluationSma3Uavs);

// One optimisation over `free` UAVs; every iteration uses a fresh stream.
void runOptimiser(benchmark::State& state, int n_uavs, const std::vector<int>& free) {
  const Scene scene(n_uavs);
  const std::vector<Plan> assumed(n_uavs, hoverPlan(kHorizon));
  const std::vector<Plan> warm(free.size(), hoverPlan(kHorizon));
  PlannerConfig config;
  config.horizon = kHorizon;
  PlanOptimizer optimizer;
  long long evaluations = 0, iterations = 0;
  std::uint64_t stream = 0;
  for (auto _ : state) {
    RandomStream rng(1, "pso", stream++);
    const PlanSearch search =
        optimizer.optimise(scene.problem(), config.pso, free, assumed, warm, rng);
    evaluations += search.evaluations;
    iterations += search.iterations;
    benchmark::DoNotOptimize(search.cost);
  }
  state.counters["evals_per_call"] =
      benchmark::Counter(static_cast<double>(evaluations), benchmark::Counter::kAvgIterations);
  state.counters["swarm_iterations"] =
      benchmark::Counter(static_cast<double>(iterations), benchmark::Counter::kAvgIterations);
  state.counters["evals_per_s"] =
      benchmark::Counter(static_cast<double>(evaluations), benchmark::Counter::kIsRate);
}

// SMA-NBO: one agent's planning call (its 2H variables; the two others hold their intentions).
void BM_SmaPlanOneAgent(benchmark::State& state) {
  runOptimiser(state, 3, {0});
}
BENCHMARK(BM_SmaPlanOneAgent)->Unit(benchmark::kMillisecond);

// Dec-POMDP NBO: one agent's planning call over the joint plan of 2 UAVs (4H variables).
void BM_DecPomdpPlan2Uavs(benchmark::State& state) {
  runOptimiser(state, 2, {0, 1});
}
BENCHMARK(BM_DecPomdpPlan2Uavs)->Unit(benchmark::kMillisecond);

// A whole SMA-NBO epoch for the team of 3 (three sequential agent calls).
void BM_SmaTeamEpoch3Uavs(benchmark::State& state) {
  const Scene scene(3);
  PlannerConfig config;
  config.algorithm = PlannerAlgorithm::sma;
  config.horizon = kHorizon;
  const std::vector<AgentView> views(3, AgentView{scene.targets, &scene.map});
  TeamPlanner planner(config, 1.0, 1);
  int epoch = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(planner.plan(epoch++, scene.uavs, views));
  }
}
BENCHMARK(BM_SmaTeamEpoch3Uavs)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace canopy::agents::planning

BENCHMARK_MAIN();
