// Planning in height (issue 53): the altitude a climb reaches, the UAV the cost sees at an
// altitude, and the climb the NBO cost picks where the answer is plain: climb when two people
// stand just outside the footprint (the doubled footprint holds them), descend when the one
// person stands straight below (finer noise, still in view), hold when the altitude is fixed.
#include "agents/planning/altitude_choice.h"

#include <gtest/gtest.h>

#include <vector>

#include "cost_test_support.h"

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
  u.climb_rate = 4.0;
  return atAltitude(u, 20.0);
}

TEST(AltitudeChoice, MeanAltitudeByHand) {
  const UavState u = freeAltitudeUav();
  // H = 5, Δ = 1 s, +4 m/s from 20 m: 24, 28, 32, 36, 40 → 32 m.
  EXPECT_DOUBLE_EQ(meanAltitude(u, 4.0, 5, 1.0), 32.0);
  // −4 m/s: 16, 12, then clamped at 10, 10, 10 → 11.6 m.
  EXPECT_DOUBLE_EQ(meanAltitude(u, -4.0, 5, 1.0), 11.6);
  EXPECT_DOUBLE_EQ(meanAltitude(u, 0.0, 5, 1.0), 20.0);
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

double climbFor(const UavState& u, const std::vector<TargetGaussian>& targets) {
  const std::vector<UavState> uavs{u};
  const PlanningProblem problem{targets, uavs, nullptr, settings(5, false)};
  const std::vector<Plan> joint{hoverPlan(5)};
  NominalCost cost;
  return chooseClimb(problem, 0, joint, joint[0], 1.0, cost);
}

TEST(AltitudeChoice, ClimbsToHoldTwoPeopleJustOutside) {
  // Two people 10 m ahead and behind: outside the 16 m footprint (±8 m) at 20 m, inside from
  // 25 m (±10 m). Of the rates tried, +2 m/s (mean altitude 26 m, ±10.4 m) and +4 m/s (32 m)
  // hold both; +2 m/s measures finer (α · 26/20 against α · 32/20).
  const std::vector<TargetGaussian> targets{target(Vec2(10, 0), Vec2::Zero(), 4.0),
                                            target(Vec2(-10, 0), Vec2::Zero(), 4.0)};
  EXPECT_DOUBLE_EQ(climbFor(freeAltitudeUav(), targets), 2.0);
}

TEST(AltitudeChoice, DescendsOverOnePersonStraightBelow) {
  // One person straight below, in view at every altitude: the lowest mean altitude has the least
  // noise (α · z / 20).
  const std::vector<TargetGaussian> targets{target(Vec2::Zero(), Vec2::Zero(), 4.0)};
  EXPECT_DOUBLE_EQ(climbFor(freeAltitudeUav(), targets), -4.0);
}

TEST(AltitudeChoice, HoldsWhenTheAltitudeIsFixed) {
  UavState fixed = freeAltitudeUav();
  fixed.z_min = fixed.z_max = 20.0;
  const std::vector<TargetGaussian> targets{target(Vec2(10, 0), Vec2::Zero(), 4.0)};
  EXPECT_DOUBLE_EQ(climbFor(fixed, targets), 0.0);
}

}  // namespace
}  // namespace canopy::agents::planning
