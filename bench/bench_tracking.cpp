// Local tracking speed (algorithms.md §4). Target: one JPDAF step (predict + update) for one agent
// with 64 targets in view plus 5 clutter points ≤ 200 µs.
//
//   build/<dir>/bench/bench_tracking --benchmark_repetitions=10 --benchmark_report_aggregates_only
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "agents/occlusion_map.h"
#include "agents/tracking/tracker.h"
#include "bench/scan_file.h"
#include "core/random.h"
#include "sensing/noise.h"

namespace canopy::agents::tracking {
namespace {

constexpr double kDt = 0.2;   // s
constexpr int kPeriod = 250;  // steps: the scene repeats every 50 s
constexpr int kClutter = 5;   // false detections per scan

// n targets on a square grid 10 m apart, each circling its grid point (radius 4 m, 0.5 m/s,
// random phase and direction), all inside the footprint of one UAV hovering over the grid's
// centre; kClutter clutter points per scan; trees (optional) observed every scan. The scans of one
// period are drawn once; the tracker runs through them again and again.
struct Scene {
  std::vector<sensing::Scan> scans;
  std::vector<Vec4> initial;
  sensing::Footprint footprint;

  Scene(int n_targets, int n_trees) {
    RandomStream rng(2024, "bench_tracking", 0);
    const int side = static_cast<int>(std::ceil(std::sqrt(n_targets)));
    const double extent = 10.0 * side;
    sensing::FootprintDef def;
    def.size = Vec2(extent, extent);
    footprint = sensing::Footprint::place(def, Vec2::Zero(), 0.0);
    const sensing::SensorQuality quality;
    const double omega = 2.0 * std::numbers::pi / (kPeriod * kDt);  // rad/s
    const double radius = 4.0;
    std::vector<Vec2> centres;
    std::vector<double> phases, turns;
    for (int t = 0; t < n_targets; ++t) {
      centres.emplace_back(10.0 * (t % side) - extent / 2 + 5.0,
                           10.0 * (t / side) - extent / 2 + 5.0);
      phases.push_back(rng.uniform(0.0, 2.0 * std::numbers::pi));
      turns.push_back(rng.bernoulli(0.5) ? 1.0 : -1.0);
    }
    auto state = [&](int t, double time) {
      const double a = phases[t] + turns[t] * omega * time;
      const double w = turns[t] * omega * radius;
      return Vec4(centres[t].x() + radius * std::cos(a), centres[t].y() + radius * std::sin(a),
                  -w * std::sin(a), w * std::cos(a));
    };
    for (int t = 0; t < n_targets; ++t) initial.push_back(state(t, 0.0));
    std::vector<Vec2> trees;
    for (int j = 0; j < n_trees; ++j) {
      trees.emplace_back(rng.uniform(-extent / 2, extent / 2),
                         rng.uniform(-extent / 2, extent / 2));
    }
    const Vec2 uav = Vec2::Zero();
    for (int k = 1; k <= kPeriod; ++k) {
      sensing::Scan scan;
      auto add = [&](const Vec2& truth, sensing::LabelId label, int id) {
        const Vec2 z = truth + rng.gaussian(sensing::rangeBearingCovariance(truth, uav, quality));
        sensing::Observation o;
        o.label = label;
        o.z = z;
        o.R = sensing::rangeBearingCovariance(z, uav, quality);
        o.truth = id;
        if (label == sensing::kTreeLabel) {
          o.radius = 1.5 + 0.1 * rng.normal();
          o.radius_variance = 0.01;
        }
        scan.observations.push_back(o);
      };
      for (int t = 0; t < n_targets; ++t) add(state(t, k * kDt).head<2>(), 1, t);
      for (int c = 0; c < kClutter; ++c) {
        const double u = rng.uniform();
        add(footprint.pointFromUnitSquare(u, rng.uniform()), 1, -1);
      }
      for (int j = 0; j < n_trees; ++j) add(trees[j], sensing::kTreeLabel, j);
      scans.push_back(std::move(scan));
    }
  }
};

// A fresh tracker for the scene: every target pre-seeded, the filter's clutter density matched to
// the scene's.
Tracker freshTracker(const Scene& scene) {
  TrackingConfig config;
  config.clutter_density = kClutter / scene.footprint.area();
  Tracker tracker(0, config);
  for (int t = 0; t < static_cast<int>(scene.initial.size()); ++t) {
    tracker.preseed(t, 1, scene.initial[t]);
  }
  return tracker;
}

// Times one agent's local step: predict, update, deleteStale. The tracker restarts with every
// period of the scene (outside the timing), so that the tracks that clutter leaves behind do not
// pile up over the thousands of periods a benchmark runs.
void runSteps(benchmark::State& state, int n_targets, int n_trees) {
  const Scene scene(n_targets, n_trees);
  const OcclusionMap map;
  Tracker tracker = freshTracker(scene);
  double tracks = 0.0, steps = 0.0, approximated = 0.0;
  int k = 0;
  for (auto _ : state) {
    tracker.predict(kDt);
    tracker.update(scene.scans[k], scene.footprint, map);
    tracker.mergeDuplicates();
    tracker.deleteStale();
    benchmark::DoNotOptimize(tracker.targets().data());
    tracks += static_cast<double>(tracker.targets().size());
    steps += 1.0;
    if (++k == kPeriod) {
      state.PauseTiming();
      approximated += static_cast<double>(tracker.diagnostics().approximated_clusters);
      tracker = freshTracker(scene);
      k = 0;
      state.ResumeTiming();
    }
  }
  state.counters["mean_tracks"] = tracks / std::max(1.0, steps);
  approximated += static_cast<double>(tracker.diagnostics().approximated_clusters);
  state.counters["approximated_per_step"] = approximated / std::max(1.0, steps);
}

void BM_TrackerStep(benchmark::State& state) {
  runSteps(state, static_cast<int>(state.range(0)), 0);
}
BENCHMARK(BM_TrackerStep)->Arg(16)->Arg(64)->Arg(256)->Unit(benchmark::kMicrosecond);

void BM_TrackerStepWithTrees(benchmark::State& state) {
  runSteps(state, 64, static_cast<int>(state.range(0)));
}
BENCHMARK(BM_TrackerStepWithTrees)->Arg(20)->Unit(benchmark::kMicrosecond);

// One scan of the shared-scan setting (bench/tracking_accuracy.cpp, seed 1 of
// `tracking_accuracy --generate N`): N targets, Poisson(5) clutter, no pre-seeded tracks, the
// tracker told the file's parameters; the 100 scans are replayed from an empty tracker.
void BM_SharedScans(benchmark::State& state) {
  const bench::ScanFile file = bench::generateScanFile(static_cast<int>(state.range(0)), 1);
  const TrackingConfig config = bench::trackerConfigFor(file, TrackConfirmation::existence);
  sensing::FootprintDef everywhere;
  everywhere.shape = sensing::FootprintShape::disc;
  everywhere.radius = 1e12;
  const sensing::Footprint footprint = sensing::Footprint::place(everywhere, Vec2::Zero(), 0.0);
  std::vector<sensing::Scan> scans(file.scans.size());
  for (std::size_t k = 0; k < scans.size(); ++k) {
    for (const Vec2& z : file.scans[k].detections) {
      sensing::Observation o;
      o.label = 1;
      o.z = z;
      o.R = file.sigma * file.sigma * Mat2::Identity();
      scans[k].observations.push_back(o);
    }
  }
  const OcclusionMap map;
  Tracker tracker(0, config);
  std::size_t k = 0;
  for (auto _ : state) {
    if (k > 0) tracker.predict(file.dt);
    tracker.update(scans[k], footprint, map);
    tracker.mergeDuplicates();
    tracker.deleteStale();
    benchmark::DoNotOptimize(tracker.targets().data());
    if (++k == scans.size()) {
      state.PauseTiming();
      tracker = Tracker(0, config);
      k = 0;
      state.ResumeTiming();
    }
  }
}
BENCHMARK(BM_SharedScans)->Arg(4)->Arg(16)->Arg(64)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace canopy::agents::tracking

BENCHMARK_MAIN();
