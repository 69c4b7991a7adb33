// Ground robots in the planner: the cost moves them as the world does (unicycle) and predicts
// what their sector camera sees exactly as sensing decides it.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "agents/occlusion_map.h"
#include "agents/planning/nominal_cost.h"
#include "sensing/sensor.h"
#include "world/world.h"

namespace canopy::agents::planning {
namespace {

constexpr double kPi = std::numbers::pi;

UavState robotAt(const Vec2& p, double heading, double turn_rate) {
  UavState u;
  u.position = p;
  u.yaw = heading;
  u.yaw_mode = world::YawMode::velocity;
  u.kind = world::AgentKind::ground;
  u.turn_rate = turn_rate;
  u.v_max = 2.0;
  u.footprint.shape = sensing::FootprintShape::sector;
  u.footprint.radius = 20.0;
  u.footprint.angle = kPi / 2;
  u.occlusion = sensing::OcclusionModel::line_of_sight;
  return u;
}

// tr P₁ of one static target with P₀ = I₄, σ_a = 1, Δ = 1 (P⁻ = 2.25 I on the position), after
// one measurement from d metres (α = 0.3: variances 0.03 d along the range, 0.03 π d across).
double seenTrace(double d) {
  const double a = 0.03 * d, b = 0.03 * kPi * d;
  return 2.25 * a / (2.25 + a) + 2.25 * b / (2.25 + b);
}

double costOf(const UavState& robot, const Vec2& target_at, const Vec2& action,
              const OcclusionMap* map) {
  TargetGaussian target;
  target.x << target_at, 0, 0;
  target.P = Mat4::Identity();
  const std::vector<TargetGaussian> targets{target};
  const std::vector<UavState> uavs{robot};
  CostSettings s;
  s.horizon = 1;
  s.terminal_penalty = false;
  NominalCost cost;
  const std::vector<int> free{0};
  cost.prepare(PlanningProblem{targets, uavs, map, s}, free, std::vector<Plan>{hoverPlan(1)});
  const std::vector<Vec2> actions{action};
  return cost.evaluate(actions);
}

TEST(GroundRobotCost, TheCostTurnsTheSectorAtTheRobotsTurnRate) {
  // Facing east at the origin, a target 10 m north: 90° off the heading, outside the ±45° view.
  // Hovering it stays unseen (tr P⁻ = 4.5). Told to go north (0.01 m/s: it turns first), after
  // Δ = 1 s it faces 1 rad (57°) at ω_max = 1: the target is 33° off, seen from 10 m. At
  // ω_max = 0.5 it faces 0.5 rad: 61° off, still unseen.
  const Vec2 north(0, 0.01);
  EXPECT_NEAR(costOf(robotAt({0, 0}, 0.0, 1.0), {0, 10}, Vec2::Zero(), nullptr), 4.5, 1e-12);
  EXPECT_NEAR(costOf(robotAt({0, 0}, 0.0, 1.0), {0, 10}, north, nullptr), seenTrace(10), 1e-12);
  EXPECT_NEAR(costOf(robotAt({0, 0}, 0.0, 0.5), {0, 10}, north, nullptr), 4.5, 1e-12);
  // Facing it, 10 m ahead, but behind a crown at (5, 0): hidden by line of sight.
  const OcclusionMap map({world::TreeDef::disc({5, 0}, 1.0)});
  EXPECT_NEAR(costOf(robotAt({0, 0}, 0.0, 1.0), {10, 0}, Vec2::Zero(), nullptr), seenTrace(10),
              1e-12);
  EXPECT_NEAR(costOf(robotAt({0, 0}, 0.0, 1.0), {10, 0}, Vec2::Zero(), &map), 4.5, 1e-12);
}

TEST(GroundRobotCost, PredictedVisibilityEqualsSensingOnAGrid) {
  // A robot at (−2, 1) facing 0.4 rad among two crowns and a wall; a static target on a grid of
  // points. The cost says "seen" (tr P₁ < 4.5) exactly where sensing puts the target in V.
  const std::vector<world::TreeDef> trees{
      world::TreeDef::disc({6, 4}, 1.5), world::TreeDef::disc({3, -2}, 1.0),
      world::TreeDef::polygon({{10, 8}, {11, 8}, {11, 16}, {10, 16}})};
  const OcclusionMap map(trees);
  const UavState robot = robotAt({-2, 1}, 0.4, 1.0);
  sensing::SensorDef camera{robot.footprint, robot.quality, true};
  world::WorldDef def;
  def.aoi = {Vec2(-30, -30), Vec2(30, 30)};
  world::UavDef body;
  body.kind = world::AgentKind::ground;
  body.start = robot.position;
  body.yaw = robot.yaw;
  def.uavs.push_back(body);
  def.trees = trees;
  int points = 0, seen = 0, hidden_in_view = 0;
  for (double x = -6; x <= 22; x += 1.25) {
    for (double y = -14; y <= 22; y += 1.25) {
      world::WorldDef with_target = def;
      with_target.targets.push_back({world::Path::constantVelocity({x, y}, Vec2::Zero())});
      const world::World world(with_target);
      RandomStream rng(1, "sensing");
      sensing::SenseScratch scratch;
      sensing::Scan scan;
      const std::vector<sensing::LabelId> labels{1};
      sense(world, world.snapshot(), 0, camera, sensing::SensingConfig{}, labels, rng, scratch,
            scan);
      const bool visible = !scan.visible.empty();
      const double cost = costOf(robot, {x, y}, Vec2::Zero(), &map);
      ASSERT_EQ(cost < 4.5 - 1e-9, visible) << "target (" << x << ", " << y << ")";
      ++points;
      seen += visible;
      hidden_in_view += !scan.in_footprint.empty() && !visible;
    }
  }
  // Not vacuous: many points seen, and some in the sector hidden behind the crowns and the wall.
  EXPECT_GT(seen, points / 10);
  EXPECT_GT(hidden_in_view, 20);
}

TEST(GroundRobotCost, ThePlannedPathIsTheWorldsMotion) {
  // Three actions of Δ = 1 s, each held for five world steps of 0.2 s.
  // Each turns 0.4–1.0 rad at 1.5 rad/s first, then drives (the second clamped to 2 m/s).
  UavState robot = robotAt({1, -1}, 2.0, 1.5);
  Plan plan;
  plan.velocities = {Vec2(-1.5, 1), Vec2(0, 3), Vec2(1, 1.5)};
  const std::vector<Vec2> planned = plannedPath(robot, plan, 1.0);
  world::WorldDef def;
  def.aoi = {Vec2(-30, -30), Vec2(30, 30)};
  world::UavDef body;
  body.kind = world::AgentKind::ground;
  body.yaw_mode = world::YawMode::velocity;
  body.start = robot.position;
  body.yaw = robot.yaw;
  body.v_max = robot.v_max;
  body.turn_rate = robot.turn_rate;
  def.uavs.push_back(body);
  world::World world(def);
  ASSERT_EQ(planned.size(), 3u);
  for (int m = 0; m < 3; ++m) {
    world.commandUav(0, plan.velocities[m]);
    for (int k = 0; k < 5; ++k) world.step(0.2);
    EXPECT_NEAR((world.snapshot().uavs[0].position - planned[m]).norm(), 0.0, 1e-4) << m;
  }
  EXPECT_GT((planned[2] - robot.position).norm(), 1.0);  // it did move
}

}  // namespace
}  // namespace canopy::agents::planning
