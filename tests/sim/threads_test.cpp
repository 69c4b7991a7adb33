// One run at 1, 2 and 4 threads (Simulation(spec, threads), `canopy run --threads N`): the same
// record.jsonl and summary.json (but for its wall-clock timing) byte for byte, for SMA-NBO in team
// scope (every agent reads its predecessors' new plans: planned one after another) and in reach
// scope (agents far apart planned side by side, also over lossy, late links), Dec-POMDP, and a
// team with ground robots. The level counts SMA-NBO plans in are checked against what the
// scenarios' geometry gives by hand, so that the parallel path is known to have run; a team-scope
// swarm large enough to share one agent's particles out counts the batches it shared.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/text_file.h"
#include "sim/run.h"
#include "sim/simulation.h"
#include "spec/loader.h"

namespace canopy::sim {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

struct Outputs {
  std::string record;
  std::string summary;  // without "timing" (wall seconds)
};

Outputs runAt(const spec::ScenarioSpec& spec, int threads, const std::string& tag) {
  const fs::path dir = fs::temp_directory_path() / ("canopy_threads_" + tag + "_" +
                                                    std::to_string(threads) + "_" +
                                                    std::to_string(::getpid()));
  RunOptions options;
  options.out_dir = dir;
  options.command_line = "threads_test";  // the same manifest at every count
  options.threads = threads;
  runScenario(spec, options);
  Outputs out;
  out.record = readTextFile(dir / "record.jsonl").value_or("");
  Json summary = Json::parse(readTextFile(dir / "summary.json").value_or("{}"));
  summary.erase("timing");
  out.summary = summary.dump();
  fs::remove_all(dir);
  return out;
}

void expectSameAtAnyThreadCount(const spec::ScenarioSpec& spec, const std::string& tag) {
  const Outputs one = runAt(spec, 1, tag);
  ASSERT_GT(one.record.size(), 1000u) << tag;
  for (const int threads : {2, 4}) {
    const Outputs many = runAt(spec, threads, tag);
    EXPECT_TRUE(many.record == one.record) << tag << ": record.jsonl differs at " << threads
                                           << " threads (" << many.record.size() << " bytes vs "
                                           << one.record.size() << ")";
    EXPECT_EQ(many.summary, one.summary) << tag << " at " << threads << " threads";
  }
}

// Every planning epoch's level count (TeamPlanner::levels) of a run at `threads`.
std::vector<int> levelsOf(const spec::ScenarioSpec& spec, int threads) {
  Simulation sim(spec, threads);
  std::vector<int> levels;
  while (!sim.done()) {
    if (sim.tick().plan) levels.push_back(sim.team().planner().levels());
  }
  return levels;
}

spec::ScenarioSpec library(const std::string& name, std::vector<std::string> overrides) {
  spec::LoadOptions load;
  load.overrides = std::move(overrides);
  return spec::loadScenario(name, load);
}

// Two pairs of UAVs 400 m apart, 10 m apart within a pair, over a few walking people and trees,
// planned with cost scope reach. reach(i) = H·Δ·v_max + circumradius(20 × 20 m) = 3·1·5 + 14.1 ≈
// 29 m: a pair's members are within reach(i) + reach(j) ≈ 58 m of each other, the pairs far
// beyond it. In the order 0, 1, 2, 3 UAV 1 reads UAV 0's new plan, UAV 3 reads UAV 2's, and
// nobody else's: two levels, {0, 2} and {1, 3}.
std::string pairsScenario(const std::string& links) {
  return R"({
  "name": "pairs", "aoi": [0, 0, 460, 60], "clock": {"dt": 0.2, "duration": 6.0}, "seed": 3,
  "uavs": [
    {"name": "a0", "start": [20, 30], "v_max": 5, "fov": {"size": [20, 20]}},
    {"name": "a1", "start": [30, 30], "v_max": 5, "fov": {"size": [20, 20]}},
    {"name": "b0", "start": [420, 30], "v_max": 5, "fov": {"size": [20, 20]}},
    {"name": "b1", "start": [430, 30], "v_max": 5, "fov": {"size": [20, 20]}}
  ],
  "targets": [
    {"name": "p1", "path": {"waypoints": [{"t": 0, "p": [18, 28]}, {"t": 6, "p": [24, 36]}]}},
    {"name": "p2", "path": {"waypoints": [{"t": 0, "p": [34, 33]}, {"t": 6, "p": [28, 25]}]}},
    {"name": "p3", "path": {"waypoints": [{"t": 0, "p": [418, 33]}, {"t": 6, "p": [426, 26]}]}},
    {"name": "p4", "path": {"waypoints": [{"t": 0, "p": [433, 28]}, {"t": 6, "p": [437, 34]}]}}
  ],
  "occluders": [{"type": "poisson", "region": [0, 0, 460, 60], "lambda": 0.01,
                 "radius": [1.0, 2.0], "seed": 5}],
  "tracking": {"preseed": true, "preseed_variance": [1, 1, 1, 1]},
  "fusion": {"method": "ci", "rounds": 2)" +
         links + R"(},
  "planner": {"algorithm": "sma", "horizon": 3, "plan_period": 1.0, "cost_scope": "reach",
              "occlusion_map": "dynamic"}
})";
}

TEST(Threads, SmaTeamScopePlansOneAfterAnotherWithTheSameRecord) {
  const spec::ScenarioSpec spec =
      library("resource_allocation", {"planner.algorithm=\"sma\"", "clock.duration=6"});
  // Team scope, links without range, loss or delay: every agent reads all its predecessors'
  // new plans, so there are as many levels as agents.
  const std::vector<int> levels = levelsOf(spec, 2);
  ASSERT_FALSE(levels.empty());
  for (const int l : levels) EXPECT_EQ(l, static_cast<int>(spec.uavs.size()));
  expectSameAtAnyThreadCount(spec, "sma_team");
}

// Six UAVs in team scope over 30 people: every level holds one agent, and each swarm's batch is
// 20·H = 100 particles × 30 tracks = 3000 ≥ PlanOptimizer::kSharedWork, so at two threads and
// more each agent's particles are evaluated side by side (PlanOptimizer::share).
std::string crowdScenario() {
  std::string uavs, targets;
  for (int i = 0; i < 6; ++i) {
    const int x = 30 + 60 * (i % 3), y = 30 + 60 * (i / 3);
    uavs += std::string(i ? ", " : "") + R"({"name": "u)" + std::to_string(i) +
            R"(", "start": [)" + std::to_string(x) + ", " + std::to_string(y) +
            R"(], "v_max": 5, "fov": {"size": [20, 20]}})";
    for (int k = 0; k < 5; ++k) {
      const int p = 5 * i + k;
      targets += std::string(p ? ", " : "") + R"({"name": "p)" + std::to_string(p) +
                 R"(", "path": {"start": [)" + std::to_string(x - 8 + 4 * k) + ", " +
                 std::to_string(y - 6 + 3 * k) + R"(], "velocity": [)" +
                 std::to_string(0.2 * (k - 2)) + ", " + std::to_string(0.1 * (2 - k)) + "]}}";
    }
  }
  return R"({"name": "crowd", "aoi": [0, 0, 180, 120], "clock": {"dt": 0.5, "duration": 2.0},
  "seed": 4, "uavs": [)" + uavs + R"(], "targets": [)" + targets + R"(],
  "occluders": [{"type": "poisson", "region": [0, 0, 180, 120], "lambda": 0.005,
                 "radius": [1.0, 2.0], "seed": 6}],
  "tracking": {"preseed": true, "preseed_variance": [1, 1, 1, 1]},
  "planner": {"algorithm": "sma", "horizon": 5, "plan_period": 1.0}
})";
}

TEST(Threads, SmaTeamScopeSwarmEvaluatesOneAgentsParticlesSideBySideWithTheSameRecord) {
  const spec::ScenarioSpec spec = spec::loadScenarioText(crowdScenario(), "crowd.json");
  ASSERT_EQ(spec.uavs.size(), 6u);
  ASSERT_EQ(spec.targets.size(), 30u);
  // Shared batches at a thread count: each epoch's levels and the batches evaluated on the pool.
  auto sharedAt = [&](int threads) {
    Simulation sim(spec, threads);
    while (!sim.done()) {
      if (sim.tick().plan) {
        EXPECT_EQ(sim.team().planner().levels(), 6);  // one agent a level
      }
    }
    return sim.team().planner().sharedBatches();
  };
  EXPECT_EQ(sharedAt(1), 0);  // no pool: the swarm evaluates on the calling thread
  // Epochs at t = 0 and 1 s at least, six agents each, every batch of every swarm on the pool:
  // the initial swarm and at least one iteration, two batches per agent and epoch.
  EXPECT_GE(sharedAt(2), 2 * 6 * 2);
  EXPECT_GE(sharedAt(4), 2 * 6 * 2);
  expectSameAtAnyThreadCount(spec, "sma_team_crowd");
}

TEST(Threads, CentralisedLeadersSearchEvaluatesItsParticlesSideBySideWithTheSameRecord) {
  std::string text = crowdScenario();
  const std::string sma = R"("algorithm": "sma")";
  text.replace(text.find(sma), sma.size(), R"("algorithm": "centralized")");
  const spec::ScenarioSpec spec = spec::loadScenarioText(text, "crowd_centralised.json");
  auto sharedAt = [&](int threads) {
    Simulation sim(spec, threads);
    while (!sim.done()) sim.tick();
    return sim.team().planner().sharedBatches();
  };
  EXPECT_EQ(sharedAt(1), 0);
  EXPECT_GE(sharedAt(2), 2 * 2);  // two epochs at least, the initial swarm and an iteration each
  expectSameAtAnyThreadCount(spec, "centralised_crowd");
}

TEST(Threads, SmaReachScopePlansFarApartAgentsSideBySideWithTheSameRecord) {
  const spec::ScenarioSpec spec = spec::loadScenarioText(pairsScenario(""), "pairs.json");
  const std::vector<int> levels = levelsOf(spec, 2);
  ASSERT_EQ(levels.size(), 7u);  // epochs at t = 0, 1, ..., 6 s
  for (const int l : levels) EXPECT_EQ(l, 2);
  EXPECT_EQ(levelsOf(spec, 1), levels);
  expectSameAtAnyThreadCount(spec, "sma_reach");
}

TEST(Threads, SmaReachScopeOverLossyLateLinksGivesTheSameRecord) {
  // Half the messages lost, the rest a step late: whether UAV 1 holds UAV 0's new plan when it
  // plans depends on the loss draws, which must be drawn in the serial loop's order.
  const spec::ScenarioSpec spec = spec::loadScenarioText(
      pairsScenario(R"(, "comm_drop": 0.5, "comm_latency": 1)"), "pairs_lossy.json");
  // Latency 1 step, an epoch every 5 steps: no plan arrives in the epoch it was made, so no
  // agent waits for another (one level).
  for (const int l : levelsOf(spec, 2)) EXPECT_EQ(l, 1);
  expectSameAtAnyThreadCount(spec, "sma_reach_lossy");
  const spec::ScenarioSpec lossy_now = spec::loadScenarioText(
      pairsScenario(R"(, "comm_drop": 0.5)"), "pairs_lossy_now.json");
  int one = 0, two = 0;
  for (const int l : levelsOf(lossy_now, 2)) {
    EXPECT_TRUE(l == 1 || l == 2) << l;
    (l == 1 ? one : two) += 1;
  }
  EXPECT_EQ(one + two, 7);
  expectSameAtAnyThreadCount(lossy_now, "sma_reach_lossy_now");
}

TEST(Threads, DecPomdpAgentsSideBySideGiveTheSameRecord) {
  expectSameAtAnyThreadCount(
      library("trajectory_handover", {"planner.algorithm=\"dec_pomdp\"", "clock.duration=6"}),
      "dec_pomdp");
}

TEST(Threads, GroundRobotsAndUavsGiveTheSameRecord) {
  expectSameAtAnyThreadCount(library("mixed_team", {"clock.duration=8"}), "mixed_team");
  expectSameAtAnyThreadCount(
      library("mixed_team", {"clock.duration=8", "planner.cost_scope=\"reach\""}),
      "mixed_team_reach");
}

TEST(Threads, CountsOutsideOneTo256AreRefused) {
  const spec::ScenarioSpec spec = library("demo", {});
  for (const int bad : {0, -1, Simulation::kMaxThreads + 1})
    EXPECT_THROW(Simulation(spec, bad), std::invalid_argument) << bad;
  EXPECT_NO_THROW(Simulation(spec, Simulation::kMaxThreads));
}

}  // namespace
}  // namespace canopy::sim
