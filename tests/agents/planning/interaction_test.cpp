#include "agents/planning/interaction.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "agents/planning/team_planner.h"

namespace canopy::agents::planning {
namespace {

// H = 5 actions of Δ = 1 s, v_max = 5 m/s, 20 × 20 m footprints: reach = 25 + √200 m; a track at
// 1 m/s travels 5 m over the horizon. Two UAVs are linked up to 2·(25 + √200) + 5 = 83.284 m apart.
const double kLinkedUpTo = 2.0 * (25.0 + std::sqrt(200.0)) + 5.0;

std::vector<UavState> uavsAt(const std::vector<double>& xs) {
  std::vector<UavState> uavs(xs.size());
  for (std::size_t i = 0; i < xs.size(); ++i) uavs[i].position = Vec2(xs[i], 0.0);
  return uavs;
}

std::vector<TargetGaussian> oneTrackAt1MetrePerSecond() {
  TargetGaussian t;
  t.x << 0.0, 50.0, 0.6, 0.8;  // |v| = 1 m/s
  t.P = Mat4::Identity();
  return {t};
}

TEST(Interaction, ReachIsTheHorizonsTravelPlusTheFootprintsCircumradius) {
  const CostSettings s;  // H = 5, Δ = 1 s, one sample per action
  EXPECT_DOUBLE_EQ(reachOf(s, UavState{}), 25.0 + std::sqrt(200.0));
}

TEST(Interaction, BlocksAreTheChainOfLinkedUavsInPlanningOrder) {
  // 0 — 1 — 2 linked pairwise just within the distance, 3 beyond it from 2, 4 alone far away.
  const double d = kLinkedUpTo - 0.01;
  const std::vector<UavState> uavs = uavsAt({0.0, d, 2 * d, 3 * d + 0.02, 1000.0});
  const std::vector<TargetGaussian> tracks = oneTrackAt1MetrePerSecond();
  const PlanningProblem problem{tracks, uavs, nullptr, CostSettings{}};
  const std::vector<int> order = {4, 2, 0, 3, 1};
  EXPECT_EQ(interactingBlocks(problem, 0, order), (std::vector<int>{2, 0, 1}));
  EXPECT_EQ(interactingBlocks(problem, 1, order), (std::vector<int>{2, 0, 1}));
  EXPECT_EQ(interactingBlocks(problem, 3, order), (std::vector<int>{3}));
  EXPECT_EQ(interactingBlocks(problem, 4, order), (std::vector<int>{4}));
}

TEST(Interaction, FasterTracksLinkUavsFartherApart) {
  // At 3 m/s a track travels 15 m: the link reaches 10 m farther than at 1 m/s.
  const std::vector<UavState> uavs = uavsAt({0.0, kLinkedUpTo + 5.0});
  std::vector<TargetGaussian> tracks = oneTrackAt1MetrePerSecond();
  const std::vector<int> order = {0, 1};
  EXPECT_EQ(interactingBlocks({tracks, uavs, nullptr, CostSettings{}}, 0, order),
            (std::vector<int>{0}));
  tracks[0].x.tail<2>() *= 3.0;
  EXPECT_EQ(interactingBlocks({tracks, uavs, nullptr, CostSettings{}}, 0, order),
            (std::vector<int>{0, 1}));
}

TEST(Interaction, BodiesThatMayTouchAreLinkedWhateverTheFootprints) {
  // Tiny footprints (reach 25.001 m each): not linked by sensing 51.1 m apart, but two bodies of
  // radius 0.5 m keeping c = 0.2 m may meet within 5·(5 + 5) + 0.5 + 0.5 + 0.2 = 51.2 m.
  std::vector<UavState> uavs = uavsAt({0.0, 51.1});
  for (UavState& u : uavs) u.footprint.size = Vec2(0.001, 0.001);
  const std::vector<TargetGaussian> none;
  const std::vector<int> order = {0, 1};
  CostSettings s;
  EXPECT_EQ(interactingBlocks({none, uavs, nullptr, s}, 0, order), (std::vector<int>{0, 1}));
  for (UavState& u : uavs) u.radius = 0.0;  // no bodies: nothing links them
  EXPECT_EQ(interactingBlocks({none, uavs, nullptr, s}, 0, order), (std::vector<int>{0}));
}

TEST(DecPomdpNbo, AnAgentKeepsTheWarmPlanOfUavsThatCannotInteractWithIt) {
  // Two pairs 500 m apart: agent 0 optimises its pair's blocks and leaves the far pair hovering
  // (no previous plan); with joint_blocks "all" it optimises them too.
  PlannerConfig c;
  c.algorithm = PlannerAlgorithm::dec_pomdp;
  c.horizon = 3;
  c.occlusion_map = OcclusionMapMode::none;
  c.pso.max_iterations = 40;
  const std::vector<UavState> uavs = uavsAt({0.0, 20.0, 500.0, 520.0});
  std::vector<TargetGaussian> belief;
  for (const double x : {5.0, 25.0, 505.0, 525.0}) {
    TargetGaussian t;
    t.x << x + 12.0, 9.0, 0.5, 0.0;  // outside every footprint now, reachable
    t.P = 4.0 * Mat4::Identity();
    belief.push_back(t);
  }
  const std::vector<AgentView> views(4, AgentView{belief, nullptr});
  const TeamPlan local = TeamPlanner(c, 1.0, 3).plan(0, uavs, views);
  for (const int far : {2, 3}) {
    EXPECT_EQ(local.reports[0].joint[far].velocities, hoverPlan(3).velocities);
    EXPECT_NE(local.reports[far].joint[far].velocities, hoverPlan(3).velocities);  // its own
  }
  for (const int near : {0, 1})
    EXPECT_NE(local.reports[0].joint[near].velocities, hoverPlan(3).velocities);
  c.joint_blocks = JointBlocks::all;
  const TeamPlan all = TeamPlanner(c, 1.0, 3).plan(0, uavs, views);
  for (const int far : {2, 3})
    EXPECT_NE(all.reports[0].joint[far].velocities, hoverPlan(3).velocities);
}

}  // namespace
}  // namespace canopy::agents::planning
