// NominalCost::prepare on a pool: the tracks' part in blocks side by side gives what one thread
// gives.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <vector>

#include "agents/planning/nominal_cost.h"
#include "core/random.h"
#include "core/task_pool.h"
#include "tests/agents/planning/cost_test_support.h"

namespace canopy::agents::planning {
namespace {

using cost_test::hoveringUav;
using cost_test::settings;
using cost_test::target;

// prepare() with a pool (its tracks in blocks side by side, from kPoolTracksFrom tracks) prepares
// what it prepares alone: every candidate costs the same bits. 40 UAVs (39 fixed on their own
// paths, so the fixed UAVs' grid is used) over 48 tracks.
TEST(NominalCost, PreparedOnAPoolTheCostsAreTheSameBits) {
  RandomStream rng(31, "prepare-pool-test");
  std::vector<UavState> uavs;
  std::vector<Plan> plans(40);
  for (int i = 0; i < 40; ++i) {
    uavs.push_back(hoveringUav(Vec2(rng.uniform(0.0, 120.0), rng.uniform(0.0, 120.0))));
    for (int m = 0; m < 5; ++m)
      plans[i].velocities.push_back(Vec2(rng.uniform(-3.0, 3.0), rng.uniform(-3.0, 3.0)));
  }
  std::vector<TargetGaussian> targets;
  for (int j = 0; j < 48; ++j) {
    targets.push_back(target(Vec2(rng.uniform(0.0, 120.0), rng.uniform(0.0, 120.0)),
                             Vec2(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0)),
                             rng.uniform(0.5, 4.0)));
  }
  ASSERT_GE(static_cast<int>(targets.size()), NominalCost::kPoolTracksFrom);
  const PlanningProblem problem{targets, uavs, nullptr, settings(5, true)};
  const int free_agents[] = {0};
  TaskPool pool(2);
  NominalCost alone, on_pool;
  alone.prepare(problem, free_agents, plans);
  on_pool.prepare(problem, free_agents, plans, &pool);
  std::vector<Vec2> actions;
  for (int k = 0; k < 16 * 5; ++k)
    actions.push_back(Vec2(rng.uniform(-5.0, 5.0), rng.uniform(-5.0, 5.0)));
  std::vector<double> expected(16), got(16);
  alone.evaluate(actions, expected);
  on_pool.evaluate(actions, got);
  for (int k = 0; k < 16; ++k) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(got[k]), std::bit_cast<std::uint64_t>(expected[k]))
        << "candidate " << k;
  }
  EXPECT_GT(*std::max_element(expected.begin(), expected.end()),
            *std::min_element(expected.begin(), expected.end()));  // the candidates differ
}

}  // namespace
}  // namespace canopy::agents::planning
