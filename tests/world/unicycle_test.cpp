// Ground robots move as unicycles (world/unicycle.h): hand-derived poses, composition, and the
// world's Box2D bodies following the same motion step by step.
#include "world/unicycle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "world/world.h"

namespace canopy::world {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(Unicycle, TurnsInPlaceAtItsRateThenDrivesAlongTheCommand) {
  // Facing east, told to drive north at 2 m/s, ω_max = 1 rad/s: δ = π/2, so it turns for
  // t_r = π/2 s without moving, then drives north.
  const Pose2 start{Vec2(3, 4), 0.0};
  const Vec2 north(0, 2);
  const Pose2 at1 = unicycleMove(start, north, 1.0, 1.0);
  EXPECT_DOUBLE_EQ(at1.heading, 1.0);  // ω_max · 1 s
  EXPECT_EQ(at1.position, start.position);
  const Pose2 at3 = unicycleMove(start, north, 1.0, 3.0);
  EXPECT_DOUBLE_EQ(at3.heading, kPi / 2);
  EXPECT_NEAR(at3.position.x(), 3.0, 1e-15);
  EXPECT_DOUBLE_EQ(at3.position.y(), 4.0 + 2.0 * (3.0 - kPi / 2));  // |c| (t − t_r)
  // The short way round: from ψ = 3 rad toward −3 rad is 2π − 6 ≈ 0.283 rad counter-clockwise.
  const Pose2 wrap =
      unicycleMove({Vec2::Zero(), 3.0}, Vec2(std::cos(-3.0), std::sin(-3.0)), 0.1, 1.0);
  EXPECT_NEAR(wrap.heading, 3.1, 1e-12);
  // Already aligned: drives the whole time; no command: holds its pose.
  const Pose2 aligned = unicycleMove({Vec2::Zero(), 0.0}, Vec2(1.5, 0), 1.0, 2.0);
  EXPECT_DOUBLE_EQ(aligned.position.x(), 3.0);
  const Pose2 held = unicycleMove(start, Vec2::Zero(), 1.0, 5.0);
  EXPECT_EQ(held.position, start.position);
  EXPECT_EQ(held.heading, start.heading);
}

TEST(Unicycle, MovingForT1ThenT2IsMovingForTheirSum) {
  const Pose2 start{Vec2(-1, 2), 2.5};
  const Vec2 c(1.2, -0.7);
  for (const double t1 : {0.1, 0.4, 1.0, 2.2}) {
    for (const double t2 : {0.2, 0.9, 3.0}) {
      const Pose2 once = unicycleMove(start, c, 0.8, t1 + t2);
      const Pose2 twice = unicycleMove(unicycleMove(start, c, 0.8, t1), c, 0.8, t2);
      EXPECT_NEAR((once.position - twice.position).norm(), 0.0, 1e-12) << t1 << " + " << t2;
      EXPECT_NEAR(wrapAngle(once.heading - twice.heading), 0.0, 1e-12) << t1 << " + " << t2;
    }
  }
}

TEST(Unicycle, TheWorldMovesAGroundRobotAsTheClosedFormAndWithinItsTurnRate) {
  WorldDef def;
  def.aoi = {Vec2(-50, -50), Vec2(50, 50)};
  UavDef robot;
  robot.kind = AgentKind::ground;
  robot.yaw_mode = YawMode::velocity;
  robot.start = Vec2(1, 1);
  robot.yaw = 0.0;
  robot.v_max = 2.0;
  robot.turn_rate = 0.8;
  def.uavs.push_back(robot);
  World world(def);
  const double dt = 0.2;
  // South-west at 3 m/s, clamped to 2: δ = −3π/4, t_r = 2.945 s; then 20 steps more.
  world.commandUav(0, Vec2(-3, -3) / std::sqrt(2.0));
  Pose2 expected{robot.start, robot.yaw};
  const Vec2 clamped = Vec2(-2, -2) / std::sqrt(2.0);
  double previous = robot.yaw;
  for (int k = 1; k <= 35; ++k) {
    world.step(dt);
    expected = unicycleMove(expected, clamped, robot.turn_rate, dt);
    const UavState state = world.snapshot().uavs[0];
    EXPECT_NEAR((state.position - expected.position).norm(), 0.0, 1e-4) << "step " << k;
    EXPECT_NEAR(wrapAngle(state.yaw - expected.heading), 0.0, 1e-5) << "step " << k;
    EXPECT_LE(std::abs(wrapAngle(state.yaw - previous)), robot.turn_rate * dt + 1e-5);
    // It moves only along its heading.
    if (state.velocity.norm() > 1e-9) {
      EXPECT_NEAR(std::atan2(state.velocity.y(), state.velocity.x()), state.yaw, 1e-5);
    }
    previous = state.yaw;
  }
  // The closed form's end point: 7 s in all, 7 − 3π/(4·0.8) s of it driving at 2 m/s.
  const double driving = 7.0 - 3.0 * kPi / 4.0 / 0.8;
  const Vec2 end = robot.start + driving * clamped;
  EXPECT_NEAR((world.snapshot().uavs[0].position - end).norm(), 0.0, 1e-4);
}

}  // namespace
}  // namespace canopy::world
