// The tracker's predicted visibility under `volumes` (issue 53): the 3-D line of sight from the
// camera to the walker's head through the map's crown volumes, as sensing tests it, against a
// geometry worked by hand.
#include <gtest/gtest.h>

#include "agents/tracking/tracker.h"
#include "agents/tracking/visibility.h"
#include "sensing/camera.h"
#include "test_support.h"

namespace canopy::agents::tracking {
namespace {

using test::discFootprint;

// One crown: a disc of radius 3 m at (10, 0) from 3 m to 9 m above the ground.
OcclusionMap highCrown() {
  world::TreeDef crown = world::TreeDef::disc(Vec2(10.0, 0.0), 3.0);
  crown.base = 3.0;
  crown.top = 9.0;
  return OcclusionMap({crown});
}

CameraOcclusion volumes(bool ground_level) {
  CameraOcclusion camera;
  camera.targets = sensing::OcclusionModel::volumes;
  camera.ground_level = ground_level;
  return camera;
}

TEST(VolumesVisibility, AGroundCameraSeesUnderAHighCrownAndAUavAboveDoesNot) {
  const OcclusionMap map = highCrown();
  const sensing::Footprint footprint = discFootprint(Vec2::Zero(), 30.0);
  const Vec2 walker(10.0, 0.0);  // under the crown's centre, head at 1.7 m
  // A robot's camera at (0, 0), 0.5 m up: the sight line enters the crown's outline at x = 7,
  // s = 0.7, at 0.5 + 1.2 · 0.7 = 1.34 m and ends at the head, 1.7 m: below the base (3 m).
  EXPECT_TRUE(targetVisible(walker, footprint, map, volumes(true), Vec2::Zero(),
                            sensing::kGroundCameraHeight));
  // The canopy model (what volumes meant to the tracker before) hides everything under a crown.
  EXPECT_FALSE(targetVisible(walker, footprint, map, CameraOcclusion{}, Vec2::Zero()));
  // A UAV straight above at 20 m: the vertical line from 20 m to 1.7 m crosses [3, 9] m.
  EXPECT_FALSE(
      targetVisible(walker, discFootprint(walker, 30.0), map, volumes(false), walker, 20.0));
  // A walker at (14, 0), outside the outline (x ∈ [7, 13]), from a UAV at (0, 0) at 20 m: the line
  // is at 20 − 18.3 · 0.5 = 10.85 m at x = 7 and 20 − 18.3 · 13/14 = 3.007 m at x = 13, so it
  // passes through [3, 9] m: hidden, where the canopy model sees it.
  const Vec2 beside(14.0, 0.0);
  EXPECT_FALSE(targetVisible(beside, footprint, map, volumes(false), Vec2::Zero(), 20.0));
  EXPECT_TRUE(targetVisible(beside, footprint, map, CameraOcclusion{}, Vec2::Zero()));
  // From 40 m the line is at 40 − 38.3 · 0.5 = 20.85 m at x = 7 and 40 − 38.3 · 13/14 = 4.44 m at
  // x = 13: through the crown too. A walker at (−5, 0), away from the crown: seen.
  EXPECT_FALSE(targetVisible(beside, footprint, map, volumes(false), Vec2::Zero(), 40.0));
  EXPECT_TRUE(targetVisible(Vec2(-5.0, 0.0), footprint, map, volumes(false), Vec2::Zero(), 40.0));
}

TEST(VolumesVisibility, SigmaPointsUnderAHighCrown) {
  // P_pos = I: the five points (10, 0), (10 ± √3, 0), (10, ±√3) are all inside the crown's outline
  // (√3 < 3). From the robot's camera at (0, 0, 0.5) each sight line stays below 1.7 m < 3 m: all
  // seen, P(visible) = 1. From a UAV straight above at 20 m every one is hidden: 0.
  const OcclusionMap map = highCrown();
  const sensing::Footprint footprint = discFootprint(Vec2::Zero(), 30.0);
  EXPECT_NEAR(visibleProbability(Vec2(10.0, 0.0), Mat2::Identity(), footprint, map, volumes(true),
                                 Vec2::Zero(), sensing::kGroundCameraHeight),
              1.0, 1e-15);
  EXPECT_EQ(
      visibleProbability(Vec2(10.0, 0.0), Mat2::Identity(), discFootprint(Vec2(10.0, 0.0), 30.0),
                         map, volumes(false), Vec2(10.0, 0.0), 20.0),
      0.0);
}

TEST(VolumesVisibility, TheTrackerCountsAMissUnderAHighCrownOnlyWhereItCouldHaveSeen) {
  // A known person at (10, 0) under the crown and a scan without a measurement: the robot's camera
  // expected to see it (a miss counted), the UAV above did not (no miss).
  TrackingConfig config;
  const OcclusionMap map = highCrown();
  for (const bool ground : {true, false}) {
    Tracker tracker(0, config);
    tracker.preseed(0, 1, Vec4(10.0, 0.0, 0.0, 0.0));
    tracker.predict(0.2);
    sensing::Scan scan;
    scan.sensor_position = ground ? Vec2::Zero() : Vec2(10.0, 0.0);
    scan.sensor_height = ground ? sensing::kGroundCameraHeight : 20.0;
    tracker.update(scan, discFootprint(scan.sensor_position, 30.0), map, volumes(ground));
    ASSERT_EQ(tracker.targets().size(), 1u);
    const TargetTrack& track = tracker.targets()[0];
    // P_pos after one prediction is about the preseed's 1 m²: every sigma point under the crown.
    EXPECT_NEAR(track.visibility, ground ? 1.0 : 0.0, 1e-15) << (ground ? "robot" : "UAV");
    EXPECT_EQ(track.expected_misses, ground ? 1 : 0) << (ground ? "robot" : "UAV");
  }
}

}  // namespace
}  // namespace canopy::agents::tracking
