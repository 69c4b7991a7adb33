// The NBO cost under the line-of-sight model against the canopy model (issue "Walls, faulty links
// and ground robots": at most 2× with a 1 000-tree map). One joint evaluation of 3 UAVs, 4 targets,
// H = 5, in a 200 × 200 m forest of 1 000 crowns (radius 0.5–1.5 m, about 8 % cover). Argument:
// 0 canopy model, 1 line of sight, 2 three ground robots instead (unicycles with 30 m, 90° sector
// cameras, line of sight).
//
//   build/release/bench/bench_line_of_sight --benchmark_repetitions=10
//   --benchmark_report_aggregates_only valgrind --tool=callgrind
//   build/release/bench/bench_line_of_sight --benchmark_min_time=0.2
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "agents/occlusion_map.h"
#include "agents/planning/nominal_cost.h"
#include "core/angles.h"
#include "core/random.h"

namespace canopy::agents::planning {
namespace {

constexpr int kHorizon = 5;

OcclusionMap forest() {
  RandomStream rng(2026, "bench.forest", 0);
  std::vector<world::TreeDef> trees;
  for (int k = 0; k < 1000; ++k) {
    trees.push_back(world::TreeDef::disc(Vec2(rng.uniform(0, 200), rng.uniform(0, 200)),
                                         rng.uniform(0.5, 1.5)));
  }
  return OcclusionMap(std::move(trees));
}

void BM_CostEvaluation1000Trees(benchmark::State& state) {
  const auto model = state.range(0) == 0 ? sensing::OcclusionModel::canopy
                                         : sensing::OcclusionModel::line_of_sight;
  const bool ground = state.range(0) == 2;
  const OcclusionMap map = forest();
  std::vector<TargetGaussian> targets;
  const Vec2 starts[] = {{80, 80}, {90, 85}, {120, 110}, {70, 130}};
  const Vec2 velocities[] = {{1.5, 0.5}, {-1, 1}, {0, -2}, {1, -1}};
  for (int j = 0; j < 4; ++j) {
    TargetGaussian t;
    t.x << starts[j], velocities[j];
    t.P = Mat4::Identity();
    targets.push_back(t);
  }
  std::vector<UavState> uavs;
  const Vec2 positions[] = {{82, 78}, {118, 112}, {95, 90}};
  for (const Vec2& p : positions) {
    UavState u;
    u.position = p;
    u.footprint.size = Vec2(20, 20);
    u.occlusion = model;
    if (ground) {
      u.kind = world::AgentKind::ground;
      u.yaw_mode = world::YawMode::velocity;
      u.v_max = 2.0;
      u.turn_rate = 1.0;
      u.footprint.shape = sensing::FootprintShape::sector;
      u.footprint.radius = 30.0;
      u.footprint.angle = 0.5 * kPi;
    }
    uavs.push_back(u);
  }
  PlannerConfig config;
  config.horizon = kHorizon;
  const PlanningProblem problem{targets, uavs, &map, CostSettings::from(config, 1.0)};
  const std::vector<int> everyone{0, 1, 2};
  const std::vector<Plan> unused(3);
  NominalCost cost;
  cost.prepare(problem, everyone, unused);
  // Ten batches of 100 joint plans, evaluated a batch at a time as the swarm hands them over.
  constexpr int kBatch = 100, kBatches = 10, kPerPlan = 3 * kHorizon;
  RandomStream rng(7, "bench", 1);
  std::vector<Vec2> plans;
  for (int k = 0; k < kBatches * kBatch * kPerPlan; ++k) {
    const double speed = rng.uniform(0, 5), heading = rng.uniform(0, kTwoPi);
    plans.push_back(speed * Vec2(std::cos(heading), std::sin(heading)));
  }
  std::vector<double> costs(kBatch);
  std::size_t k = 0;
  for (auto _ : state) {
    cost.evaluate(std::span<const Vec2>(plans).subspan((k++ % kBatches) * kBatch * kPerPlan,
                                                       kBatch * kPerPlan),
                  costs);
    benchmark::DoNotOptimize(costs.data());
  }
  state.SetItemsProcessed(state.iterations() * kBatch);
}
BENCHMARK(BM_CostEvaluation1000Trees)->ArgName("line_of_sight")->Arg(0)->Arg(1)->Arg(2);

}  // namespace
}  // namespace canopy::agents::planning

BENCHMARK_MAIN();
