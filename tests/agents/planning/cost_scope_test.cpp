// The NBO cost's scopes and clearance: cost scope "reach" against the team cost of the
// neighbourhood, and the clearance charge of UAVs with bodies (split from nominal_cost_test.cpp).
#include <gtest/gtest.h>

#include <vector>

#include "agents/planning/nominal_cost.h"
#include "core/random.h"
#include "tests/agents/planning/cost_test_support.h"

namespace canopy::agents::planning {
namespace {
using cost_test::hoveringUav;
using cost_test::settings;
using cost_test::target;
}  // namespace
}  // namespace canopy::agents::planning
namespace canopy::agents::planning {
namespace {

// Cost scope "reach" (docs/design-notes.md, issue 33) is the team cost of the problem reduced to
// the tracks a free UAV can reach and the teammates that can reach them: computed here by the
// team scope on that reduced problem, built by hand. Free UAV 0 at the origin (H = 3, v_max 5,
// 20 × 20 m footprint: reach 15 + 14.1 m); UAV 1 20 m east (a neighbour), UAV 2 1 km east.
TEST(NominalCost, ReachScopeIsTheTeamCostOfTheNeighbourhood) {
  const std::vector<UavState> uavs{hoveringUav({0, 0}), hoveringUav({20, 0}),
                                   hoveringUav({1000, 0})};
  const std::vector<TargetGaussian> all{
      target({5, 3}, {1, 0}),         // in reach
      target({200, 0}, {0, 1}, 4.0),  // beyond every reach: uncovered, charged in team scope
      target({25, -8}, {0, 0}, 2.0),  // in reach, and in UAV 1's footprint
      target({1000, 5}, {0, 0}),      // under UAV 2
  };
  const std::vector<TargetGaussian> near{all[0], all[2]};
  const std::vector<UavState> neighbours{uavs[0], uavs[1]};
  const std::vector<Plan> assumed{
      hoverPlan(3), Plan{std::vector<Vec2>{Vec2(1, 0), Vec2(1, 1), Vec2(0, 0)}}, hoverPlan(3)};
  const std::vector<Plan> assumed_near{assumed[0], assumed[1]};
  CostSettings reach = settings(3, true);
  reach.scope = CostScope::reach;
  const CostSettings team = settings(3, true);
  NominalCost scoped, reduced, whole;
  const int self[] = {0};
  scoped.prepare(PlanningProblem{all, uavs, nullptr, reach}, self, assumed);
  reduced.prepare(PlanningProblem{near, neighbours, nullptr, team}, self, assumed_near);
  whole.prepare(PlanningProblem{all, uavs, nullptr, team}, self, assumed);
  RandomStream rng(33, "reach-scope-test");
  int differs = 0;
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<Vec2> actions;
    for (int m = 0; m < 3; ++m) actions.emplace_back(rng.uniform(-5, 5), rng.uniform(-5, 5));
    const double j_reach = scoped.evaluate(actions);
    EXPECT_DOUBLE_EQ(j_reach, reduced.evaluate(actions)) << trial;
    // The track at (200, 0) is uncovered at m = H whatever UAV 0 does, so the team cost is
    // larger, by its stage costs and its share of the terminal penalty.
    EXPECT_GT(whole.evaluate(actions), j_reach) << trial;
    differs += whole.evaluate(actions) != j_reach;
  }
  EXPECT_EQ(differs, 50);
}

// Without the terminal penalty the scopes differ by a constant: the stage costs of the tracks
// out of reach do not depend on the free UAV's plan (the exact part of the argument).
TEST(NominalCost, ReachScopeWithoutPenaltyDiffersFromTeamByAConstant) {
  const std::vector<UavState> uavs{hoveringUav({0, 0}), hoveringUav({60, 0}),
                                   hoveringUav({-300, 40})};
  const std::vector<TargetGaussian> all{target({5, 3}, {1, 0}), target({65, 0}, {-1, 0}),
                                        target({-300, 45}, {0, 0}), target({10, -12}, {0, 1})};
  const std::vector<Plan> assumed{
      hoverPlan(3), Plan{std::vector<Vec2>{Vec2(-4, 0), Vec2(-4, 0), Vec2(-4, 0)}}, hoverPlan(3)};
  CostSettings reach = settings(3, false);
  reach.scope = CostScope::reach;
  NominalCost scoped, whole;
  const int self[] = {0};
  scoped.prepare(PlanningProblem{all, uavs, nullptr, reach}, self, assumed);
  whole.prepare(PlanningProblem{all, uavs, nullptr, settings(3, false)}, self, assumed);
  RandomStream rng(34, "reach-scope-constant");
  double offset = 0.0;
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<Vec2> actions;
    for (int m = 0; m < 3; ++m) actions.emplace_back(rng.uniform(-5, 5), rng.uniform(-5, 5));
    const double difference = whole.evaluate(actions) - scoped.evaluate(actions);
    if (trial == 0) offset = difference;
    EXPECT_NEAR(difference, offset, 1e-9 * (1.0 + offset)) << trial;
  }
  EXPECT_GT(offset, 1.0);  // the far track's stage costs (tr P grows from 2 m² over 3 steps)
}

}  // namespace
}  // namespace canopy::agents::planning

namespace canopy::agents::planning {
namespace {

// The clearance charge (docs/design-notes.md, "Plans that keep clear") of a UAV with a body:
// K₀ + K₁·(r_f + r_g + c − d) at each sample whose nominal position lies within r_f + r_g + c of
// a teammate's intended one, as for ground robots. Free UAV 0 hovers at the origin, UAV 1 hovers
// 1.5 m east (both r = 1 m, c = 0.2 m): each of the H = 3 samples is charged
// 10⁶ + 10⁶·(2.2 − 1.5) = 1.7·10⁶ m². UAVs without a body, or a UAV and a robot, are not.
TEST(NominalCost, AUavWithABodyIsChargedForComingWithinItsSeparationOfATeammate) {
  const std::vector<TargetGaussian> targets{target({3, 4}, {0, 0})};
  auto pair = [](double r0, double r1, world::AgentKind kind1) {
    std::vector<UavState> uavs{hoveringUav({0, 0}), hoveringUav({1.5, 0})};
    uavs[0].radius = r0;
    uavs[1].radius = r1;
    uavs[1].kind = kind1;
    return uavs;
  };
  const std::vector<Plan> plans{hoverPlan(3), hoverPlan(3)};
  const CostSettings s = settings(3, true);
  const int self[] = {0};
  auto costOf = [&](const std::vector<UavState>& uavs) {
    NominalCost cost;
    cost.prepare(PlanningProblem{targets, uavs, nullptr, s}, self, plans);
    return cost.evaluate(std::vector<Vec2>(3, Vec2::Zero()));
  };
  const double bare = costOf(pair(0.0, 0.0, world::AgentKind::uav));
  const double bodies = costOf(pair(1.0, 1.0, world::AgentKind::uav));
  EXPECT_NEAR(bodies - bare, 3 * 1.7e6, 1e-6 * 3 * 1.7e6);
  // One without a body: no separation to keep (the world does not hold them apart either).
  EXPECT_EQ(costOf(pair(1.0, 0.0, world::AgentKind::uav)), bare);
  EXPECT_EQ(costOf(pair(0.0, 1.0, world::AgentKind::uav)), bare);
  // A robot below a UAV: they never touch (different collision classes).
  const std::vector<UavState> robot_below = pair(1.0, 1.0, world::AgentKind::ground);
  std::vector<UavState> robot_bare = robot_below;
  robot_bare[0].radius = 0.0;
  EXPECT_EQ(costOf(robot_below), costOf(robot_bare));
  // Both free (a joint search): the pair is charged once per sample, as for two robots.
  const int both[] = {0, 1};
  auto jointCost = [&](const std::vector<UavState>& uavs) {
    NominalCost cost;
    cost.prepare(PlanningProblem{targets, uavs, nullptr, s}, both, plans);
    return cost.evaluate(std::vector<Vec2>(6, Vec2::Zero()));
  };
  EXPECT_NEAR(jointCost(pair(1.0, 1.0, world::AgentKind::uav)) -
                  jointCost(pair(0.0, 0.0, world::AgentKind::uav)),
              3 * 1.7e6, 1e-6 * 3 * 1.7e6);
}

// Two bodies that pass each other between two samples: the charge takes their closest approach
// on the interval, not only their distance at the samples (S = 1, Δ = 1 s, r = 1 m, c = 0.2 m).
// Free UAV 0 flies from (−2, 0) to (2, 0); UAV 1 hovers at (0, 1). At the one sample they are
// √5 ≈ 2.24 m apart (> 2.2 m), but at s = ½ only 1 m: 10⁶ + 10⁶·(2.2 − 1) = 2.2·10⁶ m².
// Both free, UAV 1 flying from (2, 1) to (−2, 1) the other way: the relative position runs from
// (−4, −1) to (4, −1), closest |(0, −1)| = 1 m at s = ½, the same charge once.
TEST(NominalCost, BodiesThatPassEachOtherBetweenSamplesAreChargedTheirClosestApproach) {
  const std::vector<TargetGaussian> targets{target({30, 40}, {0, 0})};
  CostSettings s = settings(1, false);
  s.substeps = 1;
  auto uav = [](Vec2 p, double radius) {
    UavState u = hoveringUav(p);
    u.radius = radius;
    return u;
  };
  const std::vector<Plan> plans{hoverPlan(1), hoverPlan(1)};
  const int self[] = {0};
  auto fixedCost = [&](double radius) {
    const std::vector<UavState> uavs{uav({-2, 0}, radius), uav({0, 1}, radius)};
    NominalCost cost;
    cost.prepare(PlanningProblem{targets, uavs, nullptr, s}, self, plans);
    return cost.evaluate(std::vector<Vec2>{Vec2(4, 0)});
  };
  EXPECT_NEAR(fixedCost(1.0) - fixedCost(0.0), 2.2e6, 1e-6);
  const int both[] = {0, 1};
  auto jointCost = [&](double radius) {
    const std::vector<UavState> uavs{uav({-2, 0}, radius), uav({2, 1}, radius)};
    NominalCost cost;
    cost.prepare(PlanningProblem{targets, uavs, nullptr, s}, both, plans);
    return cost.evaluate(std::vector<Vec2>{Vec2(4, 0), Vec2(-4, 0)});
  };
  EXPECT_NEAR(jointCost(1.0) - jointCost(0.0), 2.2e6, 1e-6);
}

// Cost scope "reach" leaves a teammate beyond the free agent's reach out of the information
// cost, but its body is still where its plan takes it: a robot 1 km away charges nothing to a
// free robot hovering 0.3 m from the origin (its path was once left at (0, 0) and charged
// 10⁶ + 10⁶·(0.5 + 0.5 + 0.2 − 0.3) at each of the 3 samples). The cost equals that of the
// problem without the far robot; a robot 0.5 m from the free one is charged as the rule says.
TEST(NominalCost, ReachScopeChargesATeammateOutOfReachWhereItIsNotAtTheOrigin) {
  const std::vector<TargetGaussian> targets{target({5, 3}, {1, 0})};
  auto robot = [](Vec2 p) {
    UavState u = hoveringUav(p);
    u.kind = world::AgentKind::ground;
    u.radius = 0.5;
    u.footprint.shape = sensing::FootprintShape::sector;
    u.footprint.radius = 10;
    return u;
  };
  CostSettings reach = settings(3, true);
  reach.scope = CostScope::reach;
  const int self[] = {0};
  auto costOf = [&](const std::vector<UavState>& uavs) {
    const std::vector<Plan> plans(uavs.size(), hoverPlan(3));
    NominalCost cost;
    cost.prepare(PlanningProblem{targets, uavs, nullptr, reach}, self, plans);
    return cost.evaluate(std::vector<Vec2>(3, Vec2::Zero()));
  };
  const double alone = costOf({robot({0.3, 0})});
  EXPECT_LT(alone, 1e6);  // no charge: nothing near
  EXPECT_EQ(costOf({robot({0.3, 0}), robot({1000, 0})}), alone);
  // The positive control: a teammate 0.5 m away, in reach, 0.7 m inside r_f + r_g + c = 1.2 m.
  const double near = costOf({robot({0.3, 0}), robot({0.3, 0.5})});
  // (Its camera changes the information part by far less than 10³ m²: tr P is a few m² here.)
  EXPECT_NEAR(near - alone, 3 * 1.7e6, 1e3);
}

}  // namespace
}  // namespace canopy::agents::planning
