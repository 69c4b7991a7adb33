// End to end through the simulation loop: the team's fused tracks, the dynamic occlusion map
// shared by fusion, tracks kept through an occlusion, and planners that move UAVs onto targets.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include "sim/simulation.h"
#include "sim/summary.h"
#include "spec/loader.h"

namespace canopy::sim {
namespace {

spec::ScenarioSpec load(const std::string& text, const spec::LoadOptions& options = {}) {
  return spec::loadScenarioText(text, "team_test.json", options);
}

// UAV1 sweeps west → east along y = 0 over a row of trees at y = 0 (and one at y = 30 it never
// sees); UAV2 hovers far away at y = −60 and sees no tree itself.
constexpr const char* kSweep = R"({
  "aoi": [-80, -80, 80, 80], "clock": {"dt": 0.2, "duration": 30},
  "uavs": [
    {"name": "sweeper", "fov": {"size": [16, 16]},
     "path": {"waypoints": [{"t": 0, "p": [-70, 0]}, {"t": 30, "p": [70, 0]}]}},
    {"name": "hoverer", "start": [0, -60], "fov": {"size": [16, 16]}}],
  "targets": [],
  "occluders": [
    {"type": "grid", "origin": [-50, 2], "spacing": [20, 0], "rows": 1, "cols": 6, "radius": [1.5, 3.0], "seed": 4},
    {"type": "disc", "centre": [0, 30], "radius": 2.0}]
})";

TEST(Team, SweptTreesEnterEveryMapThroughFusionWithAccurateDiscs) {
  const spec::ScenarioSpec spec = load(kSweep);
  Simulation sim(spec);
  long hoverer_observations = 0;
  while (!sim.done()) {
    hoverer_observations += static_cast<long>(sim.tick().uavs[1].scan.observations.size());
  }
  EXPECT_EQ(hoverer_observations, 0);  // every disc in the hoverer's map came through fusion
  ASSERT_EQ(spec.trees.size(), 7u);
  for (int agent = 0; agent < 2; ++agent) {
    const auto& map = sim.lastStep().beliefs[agent].trees;
    ASSERT_EQ(map.size(), 6u) << "agent " << agent;  // the row, not the tree at y = 30
    for (int k = 0; k < 6; ++k) {
      const world::TreeDef& truth = spec.trees[k];
      double best = INFINITY;
      const agents::TreeEstimate* match = nullptr;
      for (const auto& tree : map) {
        const double d = (tree.belief.x.head<2>() - truth.centre).norm();
        if (d < best) best = d, match = &tree;
      }
      EXPECT_LT(best, 0.5) << "tree " << k << " agent " << agent;
      EXPECT_NEAR(match->belief.x(2), truth.radius, 0.2) << "tree " << k << " agent " << agent;
    }
  }
}

// A target walks under a crown for 3 s while the UAV hovers above it.
constexpr const char* kOcclusion = R"({
  "aoi": [-50, -50, 50, 50], "clock": {"dt": 0.2, "duration": 12},
  "uavs": [{"start": [0, 0], "fov": {"size": [40, 40]}}],
  "targets": [{"path": {"start": [-12, 0], "velocity": [2, 0]}}],
  "occluders": [{"type": "disc", "centre": [0, 0], "radius": 3.0}],
  "tracking": {"preseed": false}
})";

TEST(Team, TrackSurvivesAThreeSecondOcclusionAndIsReassociated) {
  const spec::ScenarioSpec spec = load(kOcclusion);
  Simulation sim(spec);
  agents::TrackKey key_before{};
  int hidden_steps = 0;
  std::set<agents::TrackKey> target_keys;  // every target track the tracker ever held
  while (!sim.done()) {
    const StepRecord& step = sim.tick();
    for (const auto& track : sim.team().agents()[0].tracker().targets())
      target_keys.insert(track.key);
    const double t = step.time;
    const auto& tracks = step.beliefs[0].tracks;
    if (t >= 2.0 && t < 4.5) {  // confirmed before the crown (hidden from 4.5 s to 7.5 s)
      ASSERT_EQ(tracks.size(), 1u) << t;
      key_before = tracks[0].key;
    }
    if (step.uavs[0].scan.visible.empty() && t > 4.5) ++hidden_steps;
    if (t > 4.5 && t < 7.5) {
      ASSERT_EQ(tracks.size(), 1u) << "lost under the crown at " << t;
    }
  }
  EXPECT_GE(hidden_steps, 14);  // (7.5 − 4.5) / 0.2 − 1 steps strictly inside
  const auto& tracks = sim.lastStep().beliefs[0].tracks;
  ASSERT_EQ(tracks.size(), 1u);
  EXPECT_EQ(tracks[0].key, key_before);  // re-associated, not re-born
  EXPECT_EQ(target_keys.size(), 1u);     // not even a tentative second track
  EXPECT_LT((tracks[0].belief.x.head<2>() - sim.lastStep().targets[0].position).norm(), 1.0);
}

// Two UAVs with wide footprints each watch a pair of walking targets the whole time; no pre-seeds.
constexpr const char* kWatched = R"({
  "aoi": [-60, -60, 60, 60], "clock": {"dt": 0.2, "duration": 20},
  "uavs": [{"start": [-15, 0], "fov": {"size": [40, 40]}}, {"start": [15, 0], "fov": {"size": [40, 40]}}],
  "targets": [
    {"path": {"start": [-20, -10], "velocity": [0.3, 0.8]}},
    {"path": {"start": [-10, 5], "velocity": [0.2, -0.5]}},
    {"path": {"start": [10, 8], "velocity": [-0.1, -0.6]}},
    {"path": {"start": [20, -5], "velocity": [0.0, 0.7]}}],
  "tracking": {"preseed": false}
})";

TEST(Team, FusedTracksConvergeOnTheTruth) {
  const spec::ScenarioSpec spec = load(kWatched);
  Simulation sim(spec);
  SummaryBuilder summary(spec);
  StepObserver* const observers[] = {&summary};
  runToEnd(sim, observers);
  for (const auto& ospa : summary.ospa()) {
    // Before the first tracks are confirmed OSPA is the cut-off; it then falls to the filtered
    // position error. At about 10 m range the measurement σ is at most √(0.1·π·0.3·10) ≈ 1 m, so
    // a fused, filtered error well below 1 m is expected for every target.
    EXPECT_EQ(ospa.front(), 50.0);
    double late = 0.0;  // mean over the last 10 s
    for (std::size_t k = ospa.size() - 50; k < ospa.size(); ++k) late += ospa[k] / 50.0;
    EXPECT_LT(late, 1.0);
  }
  // Complete graph, CI with Metropolis weights 1/N: one round already gives every agent the same
  // posterior, so the agents' beliefs agree.
  std::map<agents::TrackKey, Vec4> first;
  for (const auto& track : sim.lastStep().beliefs[0].tracks) first[track.key] = track.belief.x;
  ASSERT_EQ(first.size(), 4u);
  ASSERT_EQ(sim.lastStep().beliefs[1].tracks.size(), 4u);
  for (const auto& track : sim.lastStep().beliefs[1].tracks) {
    ASSERT_TRUE(first.count(track.key));
    EXPECT_LT((first[track.key] - track.belief.x).norm(), 1e-9);
  }
}

// A lone UAV 30 m from a slow target it cannot see yet (pre-seeded track).
constexpr const char* kChase = R"({
  "aoi": [-60, -60, 60, 60], "clock": {"dt": 0.2, "duration": 15},
  "uavs": [{"start": [-30, 0], "fov": {"size": [12, 12]}}],
  "targets": [{"path": {"start": [0, 0], "velocity": [0.5, 0.5]}}],
  "planner": {"horizon": 5}
})";

class PlannedChase : public ::testing::TestWithParam<std::string> {};

TEST_P(PlannedChase, MovesTheUavToCoverTheTarget) {
  spec::LoadOptions options;
  options.overrides = {"planner.algorithm=" + GetParam()};
  const spec::ScenarioSpec spec = load(kChase, options);
  Simulation sim(spec);
  int covered_last_5s = 0;
  while (!sim.done()) {
    const StepRecord& step = sim.tick();
    if (step.time > 10.0 && !step.uavs[0].scan.visible.empty()) ++covered_last_5s;
  }
  EXPECT_EQ(covered_last_5s, 25);  // 30 m at ≤ 5 m/s: on the target within 10 s, then kept
}

INSTANTIATE_TEST_SUITE_P(Algorithms, PlannedChase,
                         ::testing::Values("sma", "dec_pomdp", "centralized"));

TEST(Team, PlanningIsDeterministicForASeed) {
  spec::LoadOptions options;
  options.seed = 3;
  const spec::ScenarioSpec a = spec::loadScenario("trajectory_handover", options);
  const spec::ScenarioSpec b = spec::loadScenario("trajectory_handover", options);
  Simulation sa(a), sb(b);
  while (!sa.done()) {
    const StepRecord& ra = sa.tick();
    const StepRecord& rb = sb.tick();
    for (std::size_t i = 0; i < a.uavs.size(); ++i) {
      ASSERT_EQ(ra.uavs[i].position, rb.uavs[i].position);
    }
  }
}

}  // namespace
}  // namespace canopy::sim
