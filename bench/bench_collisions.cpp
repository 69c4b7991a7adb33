// What bodies that collide cost (issue 27, docs/design-notes.md "Bodies that collide").
// Targets: a world of 10⁴ static trees and 16 moving bodies steps in at most 1.5× the time it
// takes without collision shapes; the NBO cost with the clearance term at most 1.3× the cost
// without it on the mixed_team planning state.
//
//   BM_ForestStep16Robots/0:  16 ground robots without bodies (radius 0): no trunks are built,
//                             nothing collides; the world as it stepped before issue 27.
//   BM_ForestStep16Robots/1:  the same robots with bodies (radius 0.5 m) among 10⁴ trunks, of
//                             which the stepped world holds those near a robot (stepped_solids).
//   BM_MixedTeamCost/R/C:     SMA-NBO cost evaluations for mixed_team's robot R (2: rover1 in the
//                             street, 3: rover2 in the park) at its first planning epoch, a-priori
//                             map, the other agents held to hovering; C = 0 without the clearance
//                             term, 1 with it.
//
//   build/release/bench/bench_collisions --benchmark_repetitions=5
//   --benchmark_report_aggregates_only
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>

#include "agents/occlusion_map.h"
#include "agents/planning/nominal_cost.h"
#include "core/random.h"
#include "sim/simulation.h"
#include "spec/forest.h"
#include "spec/loader.h"
#include "world/world.h"

namespace {
using namespace canopy;

constexpr int kRobots = 16;
constexpr double kDt = 0.2;  // s

void BM_ForestStep16Robots(benchmark::State& state) {
  const double side = 1000.0;  // m: 10⁴ trees at 0.01 per m²
  world::WorldDef def;
  def.aoi = {Vec2(0, 0), Vec2(side, side)};
  def.trees = spec::poissonForest({def.aoi, 0.01, {1.0, 3.0}, 1, std::nullopt, SIZE_MAX});
  for (int i = 0; i < kRobots; ++i) {
    world::UavDef robot;
    robot.start = side * Vec2(0.125 + 0.25 * (i % 4), 0.125 + 0.25 * (i / 4));
    robot.kind = world::AgentKind::ground;
    robot.yaw_mode = world::YawMode::velocity;
    robot.v_max = 2.0;
    robot.turn_rate = 1.0;
    robot.radius = state.range(0) ? 0.5 : 0.0;
    def.uavs.push_back(robot);
  }
  world::World world(def);
  long k = 0, steps_in_contact = 0;
  for (auto _ : state) {
    // Each robot drives a slow circle at 2 m/s: every body moves every step, and over a run
    // some meet trunks.
    const double a = 0.02 * static_cast<double>(k++);
    for (int i = 0; i < kRobots; ++i)
      world.commandUav(i, 2.0 * Vec2(std::cos(a + i), std::sin(a + i)));
    world.step(kDt);
    const world::WorldSnapshot snap = world.snapshot();
    for (const world::UavState& u : snap.uavs) steps_in_contact += !u.contacts.empty();
  }
  state.counters["trees"] = static_cast<double>(world.trees().size());
  state.counters["robot_steps_in_contact"] = static_cast<double>(steps_in_contact);
  state.counters["stepped_solids"] = world.steppedSolidCount();  // at the end
}
BENCHMARK(BM_ForestStep16Robots)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

void BM_MixedTeamCost(benchmark::State& state) {
  using namespace canopy::agents;
  using namespace canopy::agents::planning;
  const spec::ScenarioSpec spec = spec::loadScenario("mixed_team");
  const TeamConfig team = sim::teamConfig(spec);
  const OcclusionMap map(spec.trees);  // a-priori
  std::vector<TargetGaussian> targets;
  for (const spec::TargetSpec& t : spec.targets) {
    TargetGaussian g;
    g.x << t.path.positionAt(0.0), t.path.velocityAt(0.0);
    g.P = Mat4::Identity();  // the scenario's preseed variance
    targets.push_back(g);
  }
  CostSettings settings = CostSettings::from(spec.planner, spec.tracking.sigma_a);
  settings.keep_clear = state.range(1) != 0;
  const PlanningProblem problem{targets, team.uavs, &map, settings};
  const std::vector<int> self{static_cast<int>(state.range(0))};
  const std::vector<Plan> hover(team.uavs.size());
  NominalCost cost;
  cost.prepare(problem, self, hover);

  // Candidates as the swarm hands them over: batches of particles_per_step · H plans.
  const int H = settings.horizon, batch = spec.planner.pso.particles_per_step * H, batches = 10;
  RandomStream rng(7, "bench", 2);
  std::vector<Vec2> actions;
  for (int n = 0; n < batches * batch * H; ++n) {
    const double speed = rng.uniform(0, 2), heading = rng.uniform(0, 2 * std::numbers::pi);
    actions.push_back(speed * Vec2(std::cos(heading), std::sin(heading)));
  }
  std::vector<double> costs(batch);
  const std::size_t size = static_cast<std::size_t>(batch) * H;
  std::size_t k = 0;
  for (auto _ : state) {
    cost.evaluate(std::span<const Vec2>(actions).subspan((k++ % batches) * size, size), costs);
    benchmark::DoNotOptimize(costs.data());
  }
  state.SetItemsProcessed(state.iterations() * batch);
}
BENCHMARK(BM_MixedTeamCost)->ArgsProduct({{2, 3}, {0, 1}});

}  // namespace

BENCHMARK_MAIN();
