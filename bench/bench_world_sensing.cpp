// One tick of world step + sensing: 16 UAVs, 64 targets, forests of 1 000 to 100 000 trees.
// Target (issue "World, sensing and scenario files"): ≤ 1 ms with 10 000 trees, and far less
// than linear growth with the number of trees.
//   BM_WorldStepAndSense/N:   N trees at 0.01 per m² (the AOI grows with N): the trees in view
//                             stay the same, so this isolates the cost of the forest's size.
//   BM_DenserForest/N:        N trees in a fixed 1 km² AOI: more trees in every footprint, so
//                             more tree observations to draw (work that grows with what is seen).
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>

#include "sensing/sensor.h"
#include "spec/forest.h"
#include "world/world.h"

namespace {
using namespace canopy;

constexpr int kUavs = 16;
constexpr int kTargetsPerUav = 4;
constexpr double kDensity = 0.01;  // trees per m² in BM_WorldStepAndSense
constexpr double kDt = 0.2;        // s

// A target walking around a circle of radius 15 m at 1.2 m/s, sampled as timed waypoints.
world::Path circlingPath(const Vec2& centre, double phase) {
  std::vector<world::TimedPoint> points;
  const double radius = 15.0, speed = 1.2, period = 2 * std::numbers::pi * radius / speed;
  for (int i = 0; i <= 64 * 40; ++i) {
    const double t = i * period / 64;
    const double a = phase + 2 * std::numbers::pi * i / 64;
    points.push_back({t, centre + radius * Vec2(std::cos(a), std::sin(a))});
  }
  return world::Path::throughPoints(std::move(points));
}

// UAVs on a 4 x 4 grid over a square AOI of the given side, each with four targets circling
// beneath it.
world::WorldDef makeWorld(double side, double trees_per_m2) {
  world::WorldDef def;
  def.aoi = {Vec2(0, 0), Vec2(side, side)};
  for (int i = 0; i < kUavs; ++i) {
    const Vec2 centre = side * Vec2(0.125 + 0.25 * (i % 4), 0.125 + 0.25 * (i / 4));
    def.uavs.push_back({centre, 0.0, world::YawMode::velocity, 5.0});
    for (int t = 0; t < kTargetsPerUav; ++t) {
      def.targets.push_back({circlingPath(centre, 2 * std::numbers::pi * t / kTargetsPerUav)});
    }
  }
  def.trees = spec::poissonForest({def.aoi, trees_per_m2, {1.0, 3.0}, 1, std::nullopt, SIZE_MAX});
  return def;
}

void runTicks(benchmark::State& state, world::World& world) {
  const sensing::SensorDef sensor{{sensing::FootprintShape::rectangle, Vec2(20, 20), 0.0},
                                  {0.3, 2.0}};
  const sensing::SensingConfig config;
  const std::vector<sensing::LabelId> labels(kUavs * kTargetsPerUav, 1);
  std::vector<RandomStream> rng;
  for (int i = 0; i < kUavs; ++i) rng.emplace_back(1, "sensing", i);
  sensing::SenseScratch scratch;
  std::vector<sensing::Scan> scans(kUavs);
  long k = 0, visible = 0, observations = 0;
  for (auto _ : state) {
    // UAVs circle at 4 m/s so every body moves every step.
    const double a = 0.05 * static_cast<double>(k++);
    for (int i = 0; i < kUavs; ++i)
      world.commandUav(i, 4.0 * Vec2(std::cos(a + i), std::sin(a + i)));
    world.step(kDt);
    const world::WorldSnapshot truth = world.snapshot();
    for (int i = 0; i < kUavs; ++i) {
      sensing::sense(world, truth, i, sensor, config, labels, rng[i], scratch, scans[i]);
      visible += static_cast<long>(scans[i].visible.size());
      observations += static_cast<long>(scans[i].observations.size());
    }
  }
  state.counters["trees"] = static_cast<double>(world.trees().size());
  state.counters["visible_per_tick"] = static_cast<double>(visible) / static_cast<double>(k);
  state.counters["observations_per_tick"] =
      static_cast<double>(observations) / static_cast<double>(k);
}
void BM_WorldStepAndSense(benchmark::State& state) {
  const double trees = static_cast<double>(state.range(0));
  world::World world(makeWorld(std::sqrt(trees / kDensity), kDensity));
  runTicks(state, world);
}
BENCHMARK(BM_WorldStepAndSense)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMicrosecond);

void BM_DenserForest(benchmark::State& state) {
  const double side = 1000.0;  // m
  world::World world(makeWorld(side, static_cast<double>(state.range(0)) / (side * side)));
  runTicks(state, world);
}
BENCHMARK(BM_DenserForest)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
