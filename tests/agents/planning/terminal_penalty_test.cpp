// The terminal penalty at scale (agents/planning/terminal_penalty.cpp): with eight or more fixed
// UAVs an agent's cost charges the tracks by a merge of a presorted order and searches each
// track's fixed UAVs nearest first. The same joint plan evaluated with every UAV free takes the
// paper's plain loop over every track and UAV; the two must agree on every candidate.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "agents/planning/nominal_cost.h"
#include "core/random.h"
#include "tests/agents/planning/cost_test_support.h"

namespace canopy::agents::planning {
namespace {

struct Scene {
  std::vector<UavState> uavs;
  std::vector<TargetGaussian> targets;
  std::vector<Plan> plans;
};

using cost_test::target;

// UAVs and people spread over a square; people in groups, with traces from certain to lost.
Scene randomScene(RandomStream& rng, int n_uavs, int n_targets, int horizon) {
  Scene scene;
  for (int i = 0; i < n_uavs; ++i) {
    UavState u;
    u.position = Vec2(rng.uniform(0, 400), rng.uniform(0, 400));
    u.footprint.size = Vec2(20, 20);
    scene.uavs.push_back(u);
    Plan plan;
    for (int m = 0; m < horizon; ++m)
      plan.velocities.emplace_back(rng.uniform(-5, 5), rng.uniform(-5, 5));
    scene.plans.push_back(plan);
  }
  for (int j = 0; j < n_targets; ++j) {
    const Vec2 near = scene.uavs[j % n_uavs].position;
    scene.targets.push_back(target(near + Vec2(rng.uniform(-40, 40), rng.uniform(-40, 40)),
                                     Vec2(rng.uniform(-1.4, 1.4), rng.uniform(-1.4, 1.4)),
                                     std::exp(rng.uniform(-2.0, 5.0))));
  }
  return scene;
}

// UAVs hovering on a 10 m grid over people standing on grid points with equal covariances:
// many exact ties of trace and of D_i + distance, which both searches break by the lower index.
Scene tiedScene(int side, int horizon) {
  Scene scene;
  for (int r = 0; r < side; ++r) {
    for (int c = 0; c < side; ++c) {
      UavState u;
      u.position = Vec2(100.0 * c, 100.0 * r);
      u.footprint.size = Vec2(20, 20);
      scene.uavs.push_back(u);
      scene.plans.push_back(Plan{std::vector<Vec2>(horizon, Vec2::Zero())});
      scene.targets.push_back(target(Vec2(100.0 * c + 50, 100.0 * r), Vec2::Zero(), 4.0));
      scene.targets.push_back(target(Vec2(100.0 * c, 100.0 * r + 50), Vec2::Zero(), 4.0));
    }
  }
  return scene;
}

// The agent's cost of its own candidate (the others fixed at their plans) against the joint cost
// of the same plans with everyone free, for `candidates` random plans of agent `self`.
void expectBothPathsAgree(Scene scene, int self, int candidates, RandomStream& rng,
                          const std::string& where) {
  CostSettings s;
  s.horizon = static_cast<int>(scene.plans[0].velocities.size());
  s.terminal_penalty = true;
  const PlanningProblem problem{scene.targets, scene.uavs, nullptr, s};
  NominalCost agent;
  const int free_agents[] = {self};
  agent.prepare(problem, free_agents, scene.plans);
  for (int c = 0; c < candidates; ++c) {
    std::vector<Vec2> actions;
    for (int m = 0; m < s.horizon; ++m) {
      actions.emplace_back(c == 0 ? 0.0 : rng.uniform(-6, 6), c == 0 ? 0.0 : rng.uniform(-6, 6));
    }
    scene.plans[self].velocities = actions;
    const double joint = nominalCost(problem, scene.plans);  // every UAV free: the plain loop
    const double own = agent.evaluate(actions);
    // The sums run in another order (the fixed part is summed once in prepare()).
    EXPECT_NEAR(own, joint, 1e-9 * std::abs(joint)) << where << ", candidate " << c;
  }
}

TEST(TerminalPenaltyAtScale, AgreesWithThePlainLoopOnRandomSwarms) {
  RandomStream rng(48, "terminal-penalty-scale-test");
  for (int scene = 0; scene < 12; ++scene) {
    const int n_uavs = 9 + scene;  // 8 or more fixed UAVs: the fast search
    const Scene s = randomScene(rng, n_uavs, 4 * n_uavs, 3 + scene % 3);
    expectBothPathsAgree(s, scene % n_uavs, 20, rng, "random scene " + std::to_string(scene));
  }
}

TEST(TerminalPenaltyAtScale, BreaksExactTiesAsThePlainLoopDoes) {
  RandomStream rng(49, "terminal-penalty-ties-test");
  for (const int self : {0, 4, 12}) {
    expectBothPathsAgree(tiedScene(4, 3), self, 20, rng,
                         "tied scene, free UAV " + std::to_string(self));
  }
}

// The exact skip (terminal_penalty_skip.cpp) from 64 tracks that no candidate changes: the free
// UAVs' costs against the plain loop's joint cost (every UAV free there, so nothing is skipped),
// with `free_agents` free at once (a Dec-POMDP block). Returns the tracks charged one at a time
// per candidate.
// `reuse`: prepare that cost (its buffers from earlier problems) instead of a new one.
double expectSkippingAgrees(Scene scene, const std::vector<int>& free_agents, int candidates,
                            RandomStream& rng, const std::string& where,
                            NominalCost* reuse = nullptr) {
  CostSettings s;
  s.horizon = static_cast<int>(scene.plans[0].velocities.size());
  s.terminal_penalty = true;
  const PlanningProblem problem{scene.targets, scene.uavs, nullptr, s};
  NominalCost fresh;
  NominalCost& agents = reuse != nullptr ? *reuse : fresh;
  agents.prepare(problem, free_agents, scene.plans);
  for (int c = 0; c < candidates; ++c) {
    std::vector<Vec2> actions;
    for (const int f : free_agents) {
      for (int m = 0; m < s.horizon; ++m) {
        actions.emplace_back(c == 0 ? 0.0 : rng.uniform(-6, 6), c == 0 ? 0.0 : rng.uniform(-6, 6));
      }
      scene.plans[f].velocities.assign(actions.end() - s.horizon, actions.end());
    }
    const double joint = nominalCost(problem, scene.plans);  // the plain loop
    const double own = agents.evaluate(actions);
    EXPECT_NEAR(own, joint, 1e-9 * std::abs(joint)) << where << ", candidate " << c;
  }
  return static_cast<double>(agents.penaltyCharges()) / candidates;
}

// n_uavs UAVs over a square that gives each about 100 m × 100 m, `per_uav` people near each.
Scene sparseScene(RandomStream& rng, int n_uavs, int per_uav, int horizon) {
  Scene scene = randomScene(rng, n_uavs, 0, horizon);
  const double side = 100.0 * std::sqrt(static_cast<double>(n_uavs));
  for (UavState& u : scene.uavs) u.position = Vec2(rng.uniform(0, side), rng.uniform(0, side));
  for (int j = 0; j < n_uavs * per_uav; ++j) {
    const Vec2 near = scene.uavs[j % n_uavs].position;
    scene.targets.push_back(target(near + Vec2(rng.uniform(-30, 30), rng.uniform(-30, 30)),
                                   Vec2(rng.uniform(-1.4, 1.4), rng.uniform(-1.4, 1.4)),
                                   std::exp(rng.uniform(-2.0, 5.0))));
  }
  return scene;
}

TEST(TerminalPenaltySkip, AgreesWithThePlainLoopAndChargesFewTracks) {
  RandomStream rng(50, "terminal-penalty-skip-test");
  for (int scene = 0; scene < 8; ++scene) {
    const int n_uavs = 24 + 4 * scene, per_uav = 4;
    const Scene s = sparseScene(rng, n_uavs, per_uav, 3 + scene % 3);
    const double charged = expectSkippingAgrees(s, {scene % n_uavs}, 24, rng,
                                                "sparse scene " + std::to_string(scene));
    // The loop charges every uncovered track (most of n_uavs · per_uav); the skip, those near
    // the free UAV and the UAVs it displaces.
    EXPECT_LT(charged, 0.25 * n_uavs * per_uav) << "sparse scene " << scene;
  }
}

TEST(TerminalPenaltySkip, AgreesWithSeveralFreeUavsAndDenseCrowds) {
  RandomStream rng(51, "terminal-penalty-skip-dense-test");
  for (int scene = 0; scene < 6; ++scene) {
    // Crowded: the free UAVs take charges from many neighbours, whose D_i then differ.
    const Scene s = randomScene(rng, 20, 120, 3 + scene % 3);
    expectSkippingAgrees(s, {scene, scene + 7}, 16, rng, "dense scene " + std::to_string(scene));
  }
}

TEST(TerminalPenaltySkip, BreaksExactTiesAsThePlainLoopDoes) {
  RandomStream rng(52, "terminal-penalty-skip-ties-test");
  for (const int self : {0, 9, 35}) {
    expectSkippingAgrees(tiedScene(6, 3), {self}, 20, rng,
                         "tied scene, free UAV " + std::to_string(self));
  }
}

// The skip sorts a track's nearest fixed UAVs at its first search: one cost prepared for one
// scene after another (the orders of the last still in its buffers), and crowds where the free
// UAVs displace more than kSkipMaxChanged others, so that the skip hands the whole penalty to
// the nearest-first loop (which then needs every track's order).
TEST(TerminalPenaltySkip, SortsEachTracksNearestUavsWhenFirstSearched) {
  RandomStream rng(53, "terminal-penalty-lazy-order-test");
  NominalCost reused;
  for (int scene = 0; scene < 4; ++scene) {
    const int n_uavs = 30 + 6 * scene;
    const Scene s = sparseScene(rng, n_uavs, 4, 3 + scene % 3);
    expectSkippingAgrees(s, {(7 * scene) % n_uavs}, 16, rng,
                         "reused cost, scene " + std::to_string(scene), &reused);
  }
  for (int scene = 0; scene < 2; ++scene) {
    // 64 UAVs (all free in the joint cost: prepare's limit) and 512 people over 400 × 400 m,
    // four of them free.
    const Scene s = randomScene(rng, 64, 512, 3);
    expectSkippingAgrees(s, {scene, scene + 16, scene + 32, scene + 48}, 8, rng,
                         "crowd " + std::to_string(scene), &reused);
  }
}

}  // namespace
}  // namespace canopy::agents::planning
