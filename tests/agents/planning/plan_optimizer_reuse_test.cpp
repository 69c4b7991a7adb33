// A PlanOptimizer's search does not depend on the searches it ran before: TeamPlanner runs every
// one-agent level of a team in one optimiser (TeamPlanner::alone_), one agent after another.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "agents/planning/plan_optimizer.h"
#include "core/random.h"
#include "core/task_pool.h"
#include "tests/agents/planning/cost_test_support.h"

namespace canopy::agents::planning {
namespace {

using cost_test::hoveringUav;
using cost_test::settings;
using cost_test::target;

struct ReuseScene {
  std::vector<UavState> uavs;
  std::vector<TargetGaussian> targets;
  std::vector<Plan> plans;
};

// `uavs` UAVs and `tracks` tracks at random in a square of `side` m; every UAV's plan random.
ReuseScene reuseScene(std::uint64_t seed, int uavs, int tracks, double side) {
  RandomStream rng(seed, "optimiser-reuse-test");
  ReuseScene s;
  s.plans.resize(static_cast<std::size_t>(uavs));
  for (int i = 0; i < uavs; ++i) {
    s.uavs.push_back(hoveringUav(Vec2(rng.uniform(0.0, side), rng.uniform(0.0, side))));
    for (int m = 0; m < 5; ++m)
      s.plans[i].velocities.push_back(Vec2(rng.uniform(-3.0, 3.0), rng.uniform(-3.0, 3.0)));
  }
  for (int j = 0; j < tracks; ++j) {
    s.targets.push_back(target(Vec2(rng.uniform(0.0, side), rng.uniform(0.0, side)),
                               Vec2(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0)),
                               rng.uniform(0.5, 4.0)));
  }
  return s;
}

PlanSearch searchAs(PlanOptimizer& optimizer, const ReuseScene& s, int agent) {
  const PlanningProblem problem{s.targets, s.uavs, nullptr, settings(5, true)};
  const int self[] = {agent};
  RandomStream rng(7, "pso", static_cast<std::uint64_t>(agent));
  return optimizer.optimise(problem, PsoConfig{}, self, s.plans, {}, rng);
}

TEST(PlanOptimizer, ASearchDoesNotDependOnTheSearchesBeforeIt) {
  // A large search (its particles shared out on a pool, 40 tracks), then a small one, then the
  // large one for another agent: each as a fresh optimiser finds it, to the bit.
  const ReuseScene large = reuseScene(3, 12, 40, 80.0), small = reuseScene(4, 3, 5, 30.0);
  TaskPool pool(2);
  PlanOptimizer::SharedEvaluation shared{&pool, {}}, fresh_shared{&pool, {}};
  PlanOptimizer reused;
  reused.share(&shared);
  const struct {
    const ReuseScene* scene;
    int agent;
  } runs[] = {{&large, 0}, {&small, 1}, {&large, 5}, {&small, 2}};
  for (const auto& run : runs) {
    const PlanSearch got = searchAs(reused, *run.scene, run.agent);
    PlanOptimizer fresh;
    fresh.share(&fresh_shared);
    const PlanSearch expected = searchAs(fresh, *run.scene, run.agent);
    EXPECT_EQ(got.cost, expected.cost) << "agent " << run.agent;
    EXPECT_EQ(got.iterations, expected.iterations);
    EXPECT_EQ(got.evaluations, expected.evaluations);
    ASSERT_EQ(got.plans.size(), expected.plans.size());
    EXPECT_EQ(got.plans.front().velocities, expected.plans.front().velocities);
  }
  EXPECT_GT(reused.sharedBatches(), 0);  // the large searches did go to the pool
}

}  // namespace
}  // namespace canopy::agents::planning
