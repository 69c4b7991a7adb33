// A pinhole camera at an altitude (issue 53): footprints and the slant noise model against hand
// computations.
#include "sensing/camera.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sensing/footprint.h"
#include "sensing/noise.h"
#include "sensing/sensor.h"

namespace canopy::sensing {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

TEST(Camera, FovSizeIsTheFootprintAtTheDefaultAltitude) {
  const CameraDef camera = cameraForFootprint(Vec2(30, 20));
  const FootprintDef def = groundFootprint(camera, kDefaultAltitude);
  EXPECT_EQ(def.shape, FootprintShape::rectangle);
  EXPECT_EQ(def.size, Vec2(30, 20));  // the same bits
  // fov = 2 atan(15 / 20) along, 2 atan(10 / 20) across.
  EXPECT_DOUBLE_EQ(camera.fov_along, 2 * std::atan(0.75));
  EXPECT_DOUBLE_EQ(camera.fov_across, 2 * std::atan(0.5));
}

TEST(Camera, NadirAreaAtTwiceTheAltitudeIsFourTimes) {
  // Nadir, 60° by 40°: the footprint at h is 2h tan 30° by 2h tan 20°, so at 2h each side
  // doubles and the area is four times.
  const CameraDef camera = cameraWithAngles(60 * kDeg, 40 * kDeg, 0.0);
  for (const double h : {5.0, 20.0, 37.5}) {
    const Footprint low = Footprint::place(groundFootprint(camera, h), Vec2(3, 4), 0.3);
    const Footprint high = Footprint::place(groundFootprint(camera, 2 * h), Vec2(3, 4), 0.3);
    const double by_hand = 2 * h * std::tan(30 * kDeg) * 2 * h * std::tan(20 * kDeg);
    EXPECT_NEAR(low.area(), by_hand, 1e-9 * by_hand);
    EXPECT_NEAR(high.area(), 4 * by_hand, 4e-9 * by_hand);
  }
}

TEST(Camera, PitchedFootprintIsTheHandComputedTrapezoid) {
  // h = 10 m, pitch θ = 45°, vertical fov 60° (a = 30°), horizontal fov 60° (b = 30°). The near
  // edge's centre ray leaves at θ − a = 15° from nadir: x = h tan 15°; the far one at 75°:
  // x = h tan 75°. A point of the edge's centre lies at h / cos(θ ∓ a) along its ray, whose
  // component along the optical axis is h cos a / cos(θ ∓ a); the half-width is that times tan b.
  const double h = 10.0;
  const CameraDef camera = cameraWithAngles(60 * kDeg, 60 * kDeg, 45 * kDeg);
  const FootprintDef def = groundFootprint(camera, h);
  ASSERT_EQ(def.shape, FootprintShape::quad);
  const double x_near = h * std::tan(15 * kDeg);  // 2.6795
  const double x_far = h * std::tan(75 * kDeg);   // 37.3205
  const double y_near = h * std::cos(30 * kDeg) * std::tan(30 * kDeg) / std::cos(15 * kDeg);
  const double y_far = h * std::cos(30 * kDeg) * std::tan(30 * kDeg) / std::cos(75 * kDeg);
  EXPECT_NEAR(x_near, 2.679492, 1e-6);
  EXPECT_NEAR(y_far, 19.318517, 1e-6);
  const Vec2 expected[4] = {{x_near, -y_near}, {x_far, -y_far}, {x_far, y_far}, {x_near, y_near}};
  for (int c = 0; c < 4; ++c) {
    EXPECT_NEAR(def.corners[c].x(), expected[c].x(), 1e-9) << c;
    EXPECT_NEAR(def.corners[c].y(), expected[c].y(), 1e-9) << c;
  }
  // A trapezoid's area: ½ (2 y_near + 2 y_far)(x_far − x_near).
  const Footprint f = Footprint::place(def, Vec2::Zero(), 0.0);
  EXPECT_NEAR(f.area(), (y_near + y_far) * (x_far - x_near), 1e-9);
  // The ground under the UAV is outside (the near edge is 2.68 m ahead), the far centre inside.
  EXPECT_FALSE(f.contains(Vec2::Zero()));
  EXPECT_TRUE(f.contains(Vec2(x_far, 0)));
  EXPECT_FALSE(f.contains(Vec2(x_far + 1e-6, 0)));
  EXPECT_TRUE(f.contains(Vec2(0.5 * (x_near + x_far), 0.5 * (y_near + y_far) - 1e-6)));
  EXPECT_FALSE(f.contains(Vec2(0.5 * (x_near + x_far), 0.5 * (y_near + y_far) + 1e-6)));
}

TEST(Camera, PitchedFootprintTurnsWithTheHeading) {
  // Heading north (ψ = 90°): the far edge lies along +y, its right corner at (+y_far, x_far).
  const CameraDef camera = cameraWithAngles(60 * kDeg, 60 * kDeg, 45 * kDeg);
  const Footprint f =
      Footprint::place(groundFootprint(camera, 10.0), Vec2(100, 50), std::numbers::pi / 2);
  const Vec2 far_right = f.quadCorner(1);
  EXPECT_NEAR(far_right.x(), 100 + 10 * std::cos(30 * kDeg) * std::tan(30 * kDeg) /
                                       std::cos(75 * kDeg),
              1e-9);
  EXPECT_NEAR(far_right.y(), 50 + 10 * std::tan(75 * kDeg), 1e-9);
  const Aabb box = f.bounds();
  EXPECT_NEAR(box.lo.y(), 50 + 10 * std::tan(15 * kDeg), 1e-9);
  EXPECT_NEAR(box.hi.y(), 50 + 10 * std::tan(75 * kDeg), 1e-9);
}

TEST(Camera, QuadPointsAreUniformOverTheTrapezoid) {
  // The share of points in the far half (x beyond the midline) is that half's area share.
  const CameraDef camera = cameraWithAngles(60 * kDeg, 60 * kDeg, 45 * kDeg);
  const Footprint f = Footprint::place(groundFootprint(camera, 10.0), Vec2::Zero(), 0.0);
  const double x_near = f.corners[0].x(), x_far = f.corners[1].x();
  const double y_near = f.corners[3].y(), y_far = f.corners[2].y();
  const double x_mid = 0.5 * (x_near + x_far), y_mid = 0.5 * (y_near + y_far);
  // Far half: a trapezoid of parallel sides 2 y_mid and 2 y_far over (x_far − x_mid).
  const double share = (y_mid + y_far) * (x_far - x_mid) / f.area();
  int far = 0, n = 0;
  for (int i = 0; i < 200; ++i) {
    for (int j = 0; j < 200; ++j) {
      const Vec2 p = f.pointFromUnitSquare((i + 0.5) / 200, (j + 0.5) / 200);
      EXPECT_TRUE(f.contains(p));
      far += p.x() > x_mid;
      ++n;
    }
  }
  EXPECT_NEAR(static_cast<double>(far) / n, share, 0.01);
}

TEST(Camera, NoiseAtTwiceTheSlantRange) {
  // The stated model: R_h = (ℓ(h) / ℓ(h_ref)) R with ℓ(h) = √(g² + h²), h_ref = 20 m. A target
  // 15 m off the ground point: ℓ(20) = 25 m; at h = √(50² − 15²) the slant range is 50 m, twice,
  // so R doubles.
  SensorDef sensor;
  sensor.camera = cameraForFootprint(Vec2(20, 20));
  const Vec2 p(1, 2), z = p + Vec2(9, 12);  // |z − p| = 15
  const Mat2 R = rangeBearingCovariance(z, p, sensor.quality);
  const double h2 = std::sqrt(50.0 * 50.0 - 15.0 * 15.0);
  EXPECT_NEAR(slantDistance(z, p, kDefaultAltitude), 25.0, 1e-12);
  EXPECT_NEAR(slantDistance(z, p, h2), 50.0, 1e-12);
  const Mat2 R2 = measurementCovariance(z, p, h2, sensor);
  EXPECT_NEAR((R2 - 2.0 * R).norm(), 0.0, 1e-12 * R.norm());
  // At the default altitude: eq. 2's bits; without a camera: eq. 2 at any altitude.
  EXPECT_EQ(measurementCovariance(z, p, kDefaultAltitude, sensor), R);
  EXPECT_EQ(measurementCovariance(z, p, 80.0, SensorDef{}), R);
  // Straight below at 40 m: ℓ = 40 against 20, twice.
  const Mat2 below = rangeBearingCovariance(p, p, sensor.quality);
  EXPECT_NEAR((measurementCovariance(p, p, 40.0, sensor) - 2.0 * below).norm(), 0.0, 1e-12);
}

TEST(Camera, FootprintOfFollowsTheSnapshotAltitude) {
  SensorDef sensor;
  sensor.camera = cameraForFootprint(Vec2(20, 10));
  world::WorldSnapshot truth;
  truth.uavs.resize(1);
  truth.uavs[0].position = Vec2(7, 8);
  truth.uavs[0].z = 40.0;
  const Footprint f = footprintOf(truth, 0, sensor);
  EXPECT_EQ(f.shape, FootprintShape::rectangle);
  EXPECT_DOUBLE_EQ(f.area(), 4 * 200.0);
  SensorDef fixed;
  fixed.footprint.size = Vec2(20, 10);
  EXPECT_DOUBLE_EQ(footprintOf(truth, 0, fixed).area(), 200.0);  // no camera: no altitude
}

}  // namespace
}  // namespace canopy::sensing
