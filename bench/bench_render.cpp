// Rendering benchmarks: one 800×800 frame of a 200 m × 200 m AOI with 500 trees, 4 UAVs (two
// rectangle, two disc footprints), 12 targets with trails, and every agent's beliefs (12 tracks,
// 60 tree estimates and a 5-step plan each). Budget: render + PNG encode ≤ 20 ms median.
// Run: build/<dir>/bench/bench_render --benchmark_repetitions=10
// --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include "core/random.h"
#include "render/canvas.h"
#include "render/coverage.h"
#include "render/image.h"
#include "render/scene_builder.h"

namespace {

using namespace canopy;
using namespace canopy::render;

constexpr ImageSize kFrame{800, 800};

struct Fixture {
  SceneModel model;
  world::WorldSnapshot truth;
  std::vector<agents::AgentBelief> beliefs;
  TargetTrails trails;

  Fixture() {
    RandomStream rng(7, "bench_render");
    model.title = "bench";
    model.aoi = {Vec2(-100, -100), Vec2(100, 100)};
    for (int t = 0; t < 500; ++t) {
      const Vec2 c(rng.uniform(-98, 98), rng.uniform(-98, 98));
      if (t % 10 == 0) {  // one crown in ten is a polygon
        const double r = rng.uniform(1.0, 2.5);
        model.trees.push_back(world::TreeDef::polygon(
            {c + Vec2(r, 0), c + Vec2(0, r), c + Vec2(-r, 0), c + Vec2(0, -r)}));
      } else {
        model.trees.push_back(world::TreeDef::disc(c, rng.uniform(1.0, 3.0)));
      }
    }
    for (int i = 0; i < 4; ++i) {
      sensing::SensorDef sensor;
      if (i % 2) {
        sensor.footprint.shape = sensing::FootprintShape::disc;
        sensor.footprint.radius = 15.0;
      } else {
        sensor.footprint.size = Vec2(30.0, 20.0);
      }
      model.sensors.push_back(sensor);
      truth.uavs.push_back(
          {Vec2(rng.uniform(-80, 80), rng.uniform(-80, 80)), Vec2::Zero(), rng.uniform(-3, 3)});
    }
    for (int t = 0; t < 12; ++t) {
      truth.targets.push_back({Vec2(rng.uniform(-90, 90), rng.uniform(-90, 90)), Vec2(1.2, 0.5)});
    }
    for (int k = 0; k <= 25; ++k) {  // the last 5 s of walking, dt = 0.2 s
      world::WorldSnapshot s = truth;
      s.time = 0.2 * k;
      for (world::TargetState& target : s.targets)
        target.position -= 0.2 * (25 - k) * target.velocity;
      trails.add(s);
    }
    truth.time = 5.0;
    truth.step = 25;
    for (int i = 0; i < 4; ++i) {
      agents::AgentBelief& b = beliefs.emplace_back();
      for (const world::TargetState& target : truth.targets) {
        agents::TrackEstimate& e = b.tracks.emplace_back();
        e.belief.x.head<2>() = target.position + Vec2(rng.normal(), rng.normal());
        e.belief.P.topLeftCorner<2, 2>() << 4.0, 1.0, 1.0, 2.0;
        e.confirmed = true;
      }
      for (int n = 0; n < 60; ++n) {
        const world::TreeDef& tree = model.trees[static_cast<std::size_t>(n * 8 + i)];
        agents::TreeEstimate& e = b.trees.emplace_back();
        e.belief.x << tree.centre.x(), tree.centre.y(), tree.radius;
      }
      for (int h = 1; h <= 5; ++h)
        b.planned_path.push_back(truth.uavs[i].position + Vec2(3.0 * h, 1.0 * h));
    }
  }

  Scene scene() const { return buildScene(model, truth, beliefs, trails, kFrame); }
};

const Fixture& fixture() {
  static const Fixture f;
  return f;
}

void BM_BuildScene(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(fixture().scene());
}

void BM_DrawFrame(benchmark::State& state) {
  Canvas canvas(kFrame);
  const Scene scene = fixture().scene();
  Image image;
  canvas.draw(scene, image);  // starts GL outside the timing
  for (auto _ : state) canvas.draw(scene, image);
}

void BM_EncodePng(benchmark::State& state) {
  Canvas canvas(kFrame);
  const Image image = canvas.draw(fixture().scene());
  std::size_t bytes = 0;
  for (auto _ : state) bytes = encodePng(image).size();
  state.counters["png_kB"] = static_cast<double>(bytes) / 1000.0;
}

// The budgeted path: build the scene, draw it, encode the PNG.
void BM_RenderAndEncodeFrame(benchmark::State& state) {
  Canvas canvas(kFrame);
  Image image;
  canvas.draw(fixture().scene(), image);
  for (auto _ : state) {
    canvas.draw(fixture().scene(), image);
    benchmark::DoNotOptimize(encodePng(image));
  }
}

void BM_CoverageMask(benchmark::State& state) {
  CoverageCounter counter(fixture().model.aoi, kFrame);
  counter.count(fixture().truth, fixture().model.sensors);
  for (auto _ : state)
    benchmark::DoNotOptimize(counter.count(fixture().truth, fixture().model.sensors));
}

// GL work runs on llvmpipe's threads: wall-clock time is the honest measure.
BENCHMARK(BM_BuildScene)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_DrawFrame)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_EncodePng)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_RenderAndEncodeFrame)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_CoverageMask)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
