#include "agents/planning/sensing_lanes.h"
#include "sensing/camera.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "core/random.h"

namespace canopy::agents::planning {
namespace {

std::uint64_t bitsOf(double x) {
  return std::bit_cast<std::uint64_t>(x);
}

sensing::Footprint footprintAtOrigin(RandomStream& rng, sensing::FootprintShape shape) {
  sensing::FootprintDef def;
  def.shape = shape;
  def.size = Vec2(rng.uniform(5, 30), rng.uniform(5, 30));
  def.radius = rng.uniform(5, 20);
  def.angle = rng.uniform(0.3, 6.2);
  if (shape == sensing::FootprintShape::quad) {  // a pitched camera's trapezoid (issue 53)
    const double vfov = rng.uniform(0.3, 1.5), hfov = rng.uniform(0.3, 1.5);
    const double pitch = rng.uniform(0.05, 1.39 - 0.5 * vfov);
    def.corners = sensing::groundFootprint(sensing::cameraWithAngles(vfov, hfov, pitch),
                                           rng.uniform(5, 40))
                      .corners;
  }
  return sensing::Footprint::place(def, Vec2::Zero(), 0.0);
}

// Four random poses, one of them (now and then) exactly on z, or NaN.
PoseLanes randomPoses(RandomStream& rng, const Vec2& z, int trial) {
  PoseLanes pose;
  for (int k = 0; k < 4; ++k) {
    const double yaw = rng.uniform(-4, 4);
    pose.x[k] = z.x() + rng.uniform(-25, 25);
    pose.y[k] = z.y() + rng.uniform(-25, 25);
    pose.c[k] = std::cos(yaw);
    pose.s[k] = std::sin(yaw);
  }
  if (trial % 7 == 0) pose.x[1] = z.x(), pose.y[1] = z.y();
  if (trial % 11 == 0) pose.x[2] = std::numeric_limits<double>::quiet_NaN();
  return pose;
}

// Per lane, the answer of sensing's scalar footprint test, for every shape.
TEST(SensingLanes, FootprintTestIsTheScalarOnePerLane) {
  RandomStream rng(31, "sensing-lanes-test");
  int inside = 0, outside = 0;
  for (const auto shape : {sensing::FootprintShape::rectangle, sensing::FootprintShape::disc,
                           sensing::FootprintShape::sector, sensing::FootprintShape::quad}) {
    for (int trial = 0; trial < 2000; ++trial) {
      const sensing::Footprint at_origin = footprintAtOrigin(rng, shape);
      const Vec2 z(rng.uniform(-50, 50), rng.uniform(-50, 50));
      const PoseLanes pose = randomPoses(rng, z, trial);
      const M4 holds = footprintHolds(at_origin, pose, z);
      // The cost's form: the constants worked out once for the UAV (any sensor quality).
      const SensorLanes sensor = SensorLanes::of(at_origin, {rng.uniform(0.05, 3.0), 2.0});
      const M4 holds_once = footprintHolds(at_origin, sensor, pose, z);
      for (int k = 0; k < 4; ++k) {
        const bool scalar =
            at_origin.containsFrom(Vec2(pose.x[k], pose.y[k]), pose.c[k], pose.s[k], z);
        ASSERT_EQ(holds[k] != 0, scalar) << static_cast<int>(shape) << " " << trial << " " << k;
        ASSERT_EQ(holds_once[k] != 0, scalar) << static_cast<int>(shape) << " " << trial;
        (scalar ? inside : outside) += 1;
      }
    }
  }
  EXPECT_GT(inside, 2000);  // both answers are exercised
  EXPECT_GT(outside, 2000);
}

// Per lane, the bits of sensing's R(z, p), the lane on z (range 0) included.
TEST(SensingLanes, RangeBearingNoiseIsTheScalarOnePerLane) {
  RandomStream rng(32, "sensing-lanes-test");
  for (int trial = 0; trial < 2000; ++trial) {
    const sensing::SensorQuality quality{rng.uniform(0.05, 3.0), rng.uniform(0.0, 5.0)};
    const Vec2 z(rng.uniform(-50, 50), rng.uniform(-50, 50));
    const PoseLanes pose = randomPoses(rng, z, trial);
    const NoiseLanes R = rangeBearingCovariance(z, pose.x, pose.y, quality);
    // The cost's form: the quality's constants worked out once for the UAV (with its footprint's).
    const SensorLanes sensor =
        SensorLanes::of(footprintAtOrigin(rng, sensing::FootprintShape::rectangle), quality);
    const NoiseLanes R_once = rangeBearingCovariance(z, pose.x, pose.y, sensor);
    for (int k = 0; k < 4; ++k) {
      const Mat2 scalar = sensing::rangeBearingCovariance(z, Vec2(pose.x[k], pose.y[k]), quality);
      for (const NoiseLanes& lanes : {R, R_once}) {
        ASSERT_EQ(bitsOf(lanes.r00[k]), bitsOf(scalar(0, 0))) << trial << " " << k;
        ASSERT_EQ(bitsOf(lanes.r01[k]), bitsOf(scalar(0, 1))) << trial << " " << k;
        ASSERT_EQ(bitsOf(lanes.r10[k]), bitsOf(scalar(1, 0))) << trial << " " << k;
        ASSERT_EQ(bitsOf(lanes.r11[k]), bitsOf(scalar(1, 1))) << trial << " " << k;
      }
    }
  }
}

}  // namespace
}  // namespace canopy::agents::planning
