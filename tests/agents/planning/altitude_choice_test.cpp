// Planning in height (issue 53): the NBO cost at the altitude each candidate's climb rates reach
// (footprint and noise), checked against a Kalman recursion written out here; the swarm's climb
// where the answer is plain (climb when two people stand just outside the footprint, descend
// when the one person stands straight below, no climbs when the altitude is fixed); the
// planner's `volumes` visibility (a crown whose base is above the head hides a walker from the
// UAV straight above, not from a ground robot's camera at 0.5 m).
#include "agents/planning/altitude_choice.h"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>
#include <numbers>
#include <vector>

#include "agents/occlusion_map.h"
#include "agents/planning/plan_optimizer.h"
#include "cost_test_support.h"
#include "sensing/noise.h"

namespace canopy::agents::planning {
namespace {

using cost_test::settings;
using cost_test::target;

UavState freeAltitudeUav() {
  UavState u;
  u.position = Vec2::Zero();
  u.camera = sensing::cameraForFootprint(Vec2(16, 12));
  u.reference_alpha = u.quality.alpha;
  u.z = 20.0;
  u.z_min = 10.0;
  u.z_max = 60.0;
  u.climb_rate = 2.0;
  u.v_max = 0.2;  // barely moves: the altitude is the decision
  return atAltitude(u, 20.0);
}

TEST(AltitudeChoice, AtAltitudeScalesFootprintAndNoise) {
  const UavState u = freeAltitudeUav();
  EXPECT_EQ(u.footprint.size, Vec2(16, 12));  // fov.size at the default altitude, same bits
  EXPECT_DOUBLE_EQ(u.quality.alpha, 0.3);
  const UavState high = atAltitude(u, 40.0);
  EXPECT_EQ(high.footprint.size, Vec2(32, 24));
  EXPECT_DOUBLE_EQ(high.quality.alpha, 0.6);  // α · 40 / 20
  UavState plain;
  plain.footprint.size = Vec2(16, 12);
  EXPECT_EQ(atAltitude(plain, 40.0).footprint.size, Vec2(16, 12));  // no camera: unchanged
}

TEST(AltitudeChoice, FootprintGrowthByHand) {
  UavState u = freeAltitudeUav();
  u.climb_rate = 4.0;
  EXPECT_DOUBLE_EQ(footprintGrowth(u, 5.0), 2.0);   // min(60, 20 + 4·5) / 20
  EXPECT_DOUBLE_EQ(footprintGrowth(u, 20.0), 3.0);  // z_max = 60
  u.z_min = u.z_max = 20.0;
  EXPECT_FALSE(altitudeFree(u));
  EXPECT_DOUBLE_EQ(footprintGrowth(u, 5.0), 1.0);
}

// The cost of hovering at (0, 0) with the given climb rates over H = 5 steps of 1 s, written
// out: h_m = clamp(20 + Σ c), the person at (10, 0) is held when 10 ≤ 8·h_m/20 (the 16 m
// footprint's half-length grows with h), R = √(10² + h²)/√(10² + 20²) · R_eq2, and
// J = Σ_m tr(P_m[pos]) of the Kalman recursion with the NCV model (σ_a = 1, Δ = 1).
double costByHand(const std::vector<double>& climbs) {
  const UavState u = freeAltitudeUav();
  Mat4 F = Mat4::Identity();
  F(0, 2) = F(1, 3) = 1.0;
  Mat4 Q = Mat4::Zero();
  Q(0, 0) = Q(1, 1) = 0.25;                     // τ⁴/4
  Q(0, 2) = Q(2, 0) = Q(1, 3) = Q(3, 1) = 0.5;  // τ³/2
  Q(2, 2) = Q(3, 3) = 1.0;                      // τ²
  Eigen::Matrix<double, 2, 4> Hm = Eigen::Matrix<double, 2, 4>::Zero();
  Hm(0, 0) = Hm(1, 1) = 1.0;
  Mat4 P = 4.0 * Mat4::Identity();
  const Vec2 z(10, 0), p(0, 0);
  double h = 20.0, J = 0.0;
  for (const double c : climbs) {
    h = std::clamp(h + std::clamp(c, -2.0, 2.0), 10.0, 60.0);
    P = F * P * F.transpose() + Q;
    if (10.0 <= 8.0 * h / 20.0) {
      const Mat2 R = std::sqrt(100.0 + h * h) / std::sqrt(500.0) *
                     sensing::rangeBearingCovariance(z, p, {u.reference_alpha, u.quality.r0});
      const Mat2 S = Hm * P * Hm.transpose() + R;
      const Eigen::Matrix<double, 4, 2> K = P * Hm.transpose() * S.inverse();
      P = P - K * Hm * P;
    }
    J += P(0, 0) + P(1, 1);
  }
  return J;
}

TEST(AltitudeChoice, CostAtEachCandidatesAltitudeByHand) {
  const std::vector<UavState> uavs{freeAltitudeUav()};
  const std::vector<TargetGaussian> targets{target(Vec2(10, 0), Vec2::Zero(), 4.0)};
  const PlanningProblem problem{targets, uavs, nullptr, settings(5, false)};
  const std::vector<Plan> hover{hoverPlan(5)};
  NominalCost cost;
  const int free_agents[] = {0};
  cost.prepare(problem, free_agents, hover);
  ASSERT_EQ(cost.climbCount(), 5);
  const std::vector<Vec2> actions(5 * 3, Vec2::Zero());
  // Three candidates side by side: climb (held from 26 m on), hold, descend (never held).
  const std::vector<double> climbs{2, 2, 2, 2, 2, 0, 0, 0, 0, 0, -2, -2, -2, -2, -2};
  std::vector<double> J(3);
  cost.evaluate(actions, climbs, J);
  EXPECT_NEAR(J[0], costByHand({2, 2, 2, 2, 2}), 1e-9 * J[0]);
  EXPECT_NEAR(J[1], costByHand({0, 0, 0, 0, 0}), 1e-9 * J[1]);
  EXPECT_NEAR(J[2], costByHand({-2, -2, -2, -2, -2}), 1e-9 * J[2]);
  EXPECT_LT(J[0], J[1]);  // the climb holds the person from the third step on
  // A climb rate above the limit is flown at the limit, as the world does.
  const std::vector<double> fast{9, 9, 9, 9, 9};
  double J_fast = 0.0;
  cost.evaluate(std::span<const Vec2>(actions).first(5), fast, std::span<double>(&J_fast, 1));
  EXPECT_EQ(J_fast, J[0]);
  // nominalCost reads a plan's climbs.
  Plan climbing = hoverPlan(5);
  climbing.climbs = {2, 2, 2, 2, 2};
  EXPECT_EQ(nominalCost(problem, std::vector<Plan>{climbing}), J[0]);
}

Plan bestPlan(const UavState& u, const std::vector<TargetGaussian>& targets,
              const OcclusionMap* map = nullptr) {
  const std::vector<UavState> uavs{u};
  const PlanningProblem problem{targets, uavs, map, settings(5, false)};
  const std::vector<Plan> hover{hoverPlan(5)};
  PlanOptimizer optimizer;
  RandomStream rng(53, "pso", 0);
  const int free_agents[] = {0};
  return optimizer.optimise(problem, PsoConfig{}, free_agents, hover, {}, rng).plans[0];
}

TEST(AltitudeChoice, SwarmClimbsToHoldTwoPeopleJustOutside) {
  // Two people 10 m ahead and behind: outside the 16 m footprint (±8 m) at 20 m, inside from
  // 25 m (±10 m); the UAV cannot fly to both (0.2 m/s). Climbing holds both.
  const std::vector<TargetGaussian> targets{target(Vec2(10, 0), Vec2::Zero(), 4.0),
                                            target(Vec2(-10, 0), Vec2::Zero(), 4.0)};
  const Plan plan = bestPlan(freeAltitudeUav(), targets);
  ASSERT_EQ(plan.climbs.size(), 5u);
  EXPECT_GT(plan.climb(0), 1.0);
}

TEST(AltitudeChoice, SwarmDescendsOverOnePersonStraightBelow) {
  // In view at every altitude: the lower, the finer (ℓ(h) = h straight below).
  const std::vector<TargetGaussian> targets{target(Vec2::Zero(), Vec2::Zero(), 4.0)};
  const Plan plan = bestPlan(freeAltitudeUav(), targets);
  ASSERT_EQ(plan.climbs.size(), 5u);
  EXPECT_LT(plan.climb(0), -1.0);
}

TEST(AltitudeChoice, NoClimbsWhenTheAltitudeIsFixed) {
  UavState fixed = freeAltitudeUav();
  fixed.z_min = fixed.z_max = 20.0;
  const std::vector<TargetGaussian> targets{target(Vec2(10, 0), Vec2::Zero(), 4.0)};
  EXPECT_TRUE(bestPlan(fixed, targets).climbs.empty());
}

// The information J loses to a crown: the cost of hovering with the map against without it.
double costWith(const UavState& agent, const OcclusionMap* map) {
  const std::vector<UavState> uavs{agent};
  const std::vector<TargetGaussian> targets{target(Vec2(10, 0), Vec2::Zero(), 4.0)};
  const std::vector<Plan> hover{hoverPlan(3)};
  return nominalCost({targets, uavs, map, settings(3, false)}, hover);
}

TEST(AltitudeChoice, VolumesInThePlannerAsInTheSensor) {
  // A walker at (10, 0) under a crown of radius 3 whose base is 3 m (above the 1.7 m head).
  world::TreeDef crown = world::TreeDef::disc(Vec2(10, 0), 3.0);
  crown.base = 3.0;
  crown.top = 12.0;
  const OcclusionMap high({crown});
  crown.base = 0.0;
  const OcclusionMap low({crown});
  // A UAV straight above (camera at 20 m): the sight line crosses the crown from 12 m to 3 m.
  UavState uav = freeAltitudeUav();
  uav.position = Vec2(10, 0);
  uav.occlusion = sensing::OcclusionModel::volumes;
  EXPECT_EQ(costWith(uav, &high), costWith(uav, &low));
  EXPECT_GT(costWith(uav, &high), costWith(uav, nullptr));
  // A ground robot 5 m away facing it, its camera at 0.5 m: the line stays under 1.7 m < 3 m.
  UavState robot;
  robot.position = Vec2(5, 0);
  robot.kind = world::AgentKind::ground;
  robot.footprint.shape = sensing::FootprintShape::sector;
  robot.footprint.radius = 20.0;
  robot.footprint.angle = std::numbers::pi / 2;
  robot.occlusion = sensing::OcclusionModel::volumes;
  EXPECT_EQ(costWith(robot, &high), costWith(robot, nullptr));
  EXPECT_GT(costWith(robot, &low), costWith(robot, &high));  // a crown from the ground hides it
  // Under the canopy model a crown hides what lies under it, whatever its base.
  robot.occlusion = sensing::OcclusionModel::canopy;
  EXPECT_EQ(costWith(robot, &high), costWith(robot, &low));
}

}  // namespace
}  // namespace canopy::agents::planning
