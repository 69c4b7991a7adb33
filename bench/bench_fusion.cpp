// Distributed fusion: one full step of a 16-UAV team sharing 64 target tracks (budget: 2 ms for
// CI with L = 5), its variants, and the Hungarian solver on its own.
//   build/<dir>/bench/bench_fusion [--benchmark_filter=...]
#include <benchmark/benchmark.h>

#include <vector>

#include "agents/fusion/hungarian.h"
#include "agents/fusion/team_fusion.h"
#include "core/random.h"

namespace canopy::agents::fusion {
namespace {

constexpr int kAgents = 16;
constexpr int kTargets = 64;

/// A team's lists, the same input to every timed step (fusion reads them and writes its result
/// into `fused`). Targets sit on an 8 × 8 grid 25 m apart; each agent's estimate is off by a little
/// noise, with its own covariance.
struct BenchTeam {
  BenchTeam(int trees, bool shared_keys, double spacing) {
    RandomStream rng(42, "bench.fusion");
    targets.resize(kAgents);
    tree_lists.resize(kAgents);
    for (int a = 0; a < kAgents; ++a) {
      positions.push_back(spacing * Vec2(a % 4, a / 4));
      for (int t = 0; t < kTargets; ++t) {
        tracking::TargetTrack track;
        track.key = shared_keys ? TrackKey{-1, t} : TrackKey{a, t};
        track.status = tracking::TrackStatus::confirmed;
        track.detected = rng.bernoulli(0.5);
        const Vec4 truth(25.0 * (t % 8), 25.0 * (t / 8), 1.0, 0.0);
        track.posterior.x =
            truth + 0.3 * Vec4(rng.normal(), rng.normal(), rng.normal(), rng.normal());
        Mat4 B;
        for (int k = 0; k < 16; ++k) B(k / 4, k % 4) = rng.uniform(-0.3, 0.3);
        track.posterior.P = B * B.transpose();
        track.posterior.P.diagonal() += Vec4(1.0, 1.2, 0.5, 0.6);
        track.prior = {track.posterior.x, 2.0 * track.posterior.P};
        targets[a].push_back(track);
      }
      for (int t = 0; t < trees; ++t) {
        tracking::TreeTrack tree;
        tree.key = shared_keys ? TrackKey{-1, 1000 + t} : TrackKey{a, 1000 + t};
        tree.label = sensing::kTreeLabel;
        tree.status = tracking::TrackStatus::confirmed;
        tree.posterior.x << 12.5 + 25.0 * (t % 8), 12.5 + 25.0 * (t / 8), 2.0;
        tree.posterior.x.head<2>() += 0.3 * Vec2(rng.normal(), rng.normal());
        tree.posterior.P = Eigen::Vector3d(0.5, 0.5, 0.05).asDiagonal();
        tree.prior = tree.posterior;
        tree_lists[a].push_back(tree);
      }
    }
    for (int a = 0; a < kAgents; ++a) inputs.push_back({targets[a], tree_lists[a], positions[a]});
  }

  std::vector<Vec2> positions;
  std::vector<std::vector<tracking::TargetTrack>> targets;
  std::vector<std::vector<tracking::TreeTrack>> tree_lists;
  std::vector<AgentTracks> inputs;
  FusedTracks fused;  // reused from step to step, as Team does
};

/// One timed fuse() per iteration, the copy of the inputs into the fused lists included; the
/// untimed first step warms the buffers up, as in a running simulation.
void runFusion(benchmark::State& state, const FusionConfig& config, BenchTeam& team) {
  TeamFusion fusion(config, kAgents, 1);
  fusion.fuse(team.inputs, team.fused);
  for (auto _ : state) fusion.fuse(team.inputs, team.fused);
  state.counters["agents"] = kAgents;
  state.counters["targets"] = kTargets;
}

FusionMethod methodOf(const benchmark::State& state) {
  return static_cast<FusionMethod>(state.range(0));
}

/// The budgeted case (arg 0 = CI): keys already shared, complete graph, L = 5.
void BM_FuseSharedTracks(benchmark::State& state) {
  BenchTeam team(0, true, 0.0);
  FusionConfig config;
  config.method = methodOf(state);
  runFusion(state, config, team);
}
BENCHMARK(BM_FuseSharedTracks)
    ->ArgName("method")
    ->Arg(static_cast<int>(FusionMethod::ci))
    ->Arg(static_cast<int>(FusionMethod::hcmci))
    ->Arg(static_cast<int>(FusionMethod::observer_average))
    ->Unit(benchmark::kMicrosecond);

/// The first step of a team: every key differs, so every link runs the gated Hungarian.
void BM_FuseFirstStep(benchmark::State& state) {
  BenchTeam team(0, false, 0.0);
  runFusion(state, FusionConfig{}, team);
}
BENCHMARK(BM_FuseFirstStep)->Unit(benchmark::kMicrosecond);

/// Targets plus 64 trees (the dynamic occlusion maps), CI.
void BM_FuseWithTrees(benchmark::State& state) {
  BenchTeam team(64, true, 0.0);
  runFusion(state, FusionConfig{}, team);
}
BENCHMARK(BM_FuseWithTrees)->Unit(benchmark::kMicrosecond);

/// UAVs on a 4 × 4 grid 100 m apart with a 150 m range (2 to 8 neighbours each), 30 % losses.
void BM_FuseRangeLimitedLossy(benchmark::State& state) {
  BenchTeam team(0, true, 100.0);
  FusionConfig config;
  config.comm_range = 150.0;
  config.comm_drop = 0.3;
  runFusion(state, config, team);
}
BENCHMARK(BM_FuseRangeLimitedLossy)->Unit(benchmark::kMicrosecond);

void BM_Hungarian(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  RandomStream rng(7, "bench.hungarian");
  std::vector<double> cost(static_cast<std::size_t>(n) * n);
  for (double& value : cost) value = rng.uniform(0.0, 100.0);
  Hungarian solver;
  for (auto _ : state) benchmark::DoNotOptimize(solver.solve(cost, n, n).data());
}
BENCHMARK(BM_Hungarian)->Arg(8)->Arg(64)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace canopy::agents::fusion

BENCHMARK_MAIN();
