// The scenario fields of issue 53 (altitude, camera, crown heights): defaults that change
// nothing, values read back from the effective configuration, and bad values refused naming the
// field.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "spec/error.h"
#include "spec/loader.h"

namespace canopy::spec {
namespace {

std::string scenario(const std::string& uav, const std::string& occluder = "") {
  return R"({"aoi": [0, 0, 100, 50], "uavs": [{"start": [10, 10], )" + uav +
         R"(}], "occluders": [)" + occluder + "]}";
}

std::string errorOf(const std::string& text) {
  try {
    loadScenarioText(text, "height.json");
  } catch (const ScenarioError& e) {
    return e.what();
  }
  return "";
}

TEST(HeightFields, AbsentFieldsKeepThePaperModelAndWriteNothing) {
  const ScenarioSpec spec = loadScenarioText(
      scenario(R"("fov": {"size": [20, 14]})", R"({"type": "disc", "centre": [5, 5], "radius": 1})"),
      "plain.json");
  EXPECT_FALSE(spec.uavs[0].sensor.camera.has_value());
  EXPECT_EQ(spec.effective_config.find("\"z\""), std::string::npos);
  EXPECT_EQ(spec.effective_config.find("camera"), std::string::npos);
  EXPECT_EQ(spec.effective_config.find("crown_base"), std::string::npos);
  EXPECT_EQ(spec.trees[0].base, 0.0);
  EXPECT_TRUE(std::isinf(spec.trees[0].top));
}

TEST(HeightFields, AltitudeAndCameraAreReadAndReloadToTheSameBits) {
  const ScenarioSpec spec = loadScenarioText(
      scenario(R"("fov": {"size": [20, 14]}, "z": 30, "z_max": 50, "camera": {"pitch": 0.4})",
               R"({"type": "disc", "centre": [5, 5], "radius": 1, "crown_base": 3,
                   "crown_top": 9})"),
      "height.json");
  const UavSpec& uav = spec.uavs[0];
  ASSERT_TRUE(uav.sensor.camera.has_value());
  EXPECT_EQ(uav.body.z, 30.0);
  EXPECT_EQ(uav.body.z_min, 30.0);  // default: z
  EXPECT_EQ(uav.body.z_max, 50.0);
  EXPECT_EQ(uav.body.climb_rate, 2.0);
  // The angles default to those of fov.size at 20 m: 2 atan(10/20) along, 2 atan(7/20) across.
  EXPECT_DOUBLE_EQ(uav.sensor.camera->fov_along, 2 * std::atan(0.5));
  EXPECT_DOUBLE_EQ(uav.sensor.camera->fov_across, 2 * std::atan(0.35));
  EXPECT_EQ(uav.sensor.camera->pitch, 0.4);
  EXPECT_EQ(spec.trees[0].base, 3.0);
  EXPECT_EQ(spec.trees[0].top, 9.0);
  const ScenarioSpec again = loadScenarioText(spec.effective_config, "again.json");
  EXPECT_EQ(again.effective_config, spec.effective_config);
  EXPECT_EQ(again.uavs[0].sensor.camera->nadir_size, uav.sensor.camera->nadir_size);
  EXPECT_EQ(again.uavs[0].sensor.camera->fov_along, uav.sensor.camera->fov_along);
  EXPECT_EQ(again.trees[0].top, 9.0);
}

TEST(HeightFields, BadValuesAreRefusedNamingTheField) {
  EXPECT_NE(errorOf(scenario(R"("z": 20, "z_min": 25)")).find("uavs[0].z_min"), std::string::npos);
  EXPECT_NE(errorOf(scenario(R"("z": 20, "z_max": 15)")).find("uavs[0].z_max"), std::string::npos);
  EXPECT_NE(errorOf(scenario(R"("z": -1)")).find("uavs[0].z"), std::string::npos);
  EXPECT_NE(errorOf(scenario(R"("z": 2e4)")).find("uavs[0].z"), std::string::npos);
  // pitch + vfov/2 ≤ 80°: 1.2 + 0.4 rad = 91.7°.
  EXPECT_NE(errorOf(scenario(R"("camera": {"vfov": 0.8, "pitch": 1.2})"))
                .find("uavs[0].camera.pitch"),
            std::string::npos);
  EXPECT_NE(errorOf(scenario(R"("camera": {"hfov": 3.2})")).find("uavs[0].camera.hfov"),
            std::string::npos);
  EXPECT_NE(errorOf(scenario(R"("fov": {"radius": 5}, "z": 30)")).find("uavs[0].fov"),
            std::string::npos);
  EXPECT_NE(errorOf(scenario(R"("z": 20)", R"({"type": "disc", "centre": [5, 5], "radius": 1,
                                               "crown_base": 5, "crown_top": 4})"))
                .find("occluders[0].crown_top"),
            std::string::npos);
  // A ground robot has no altitude: an unknown field.
  EXPECT_NE(errorOf(scenario(R"("kind": "ground", "z": 30)")).find("uavs[0].z"),
            std::string::npos);
}

// Scripted paths with a z (issue 53).
std::string scripted(const std::string& fields, const std::string& waypoints) {
  return R"({"aoi": [0, 0, 100, 50], "uavs": [{)" + fields + R"("path": {"waypoints": [)" +
         waypoints + "]}}]}";
}

TEST(HeightFields, WaypointAltitudesMakeAProfileAndReloadToTheSameBits) {
  const ScenarioSpec spec = loadScenarioText(
      scripted(R"("climb_rate": 3, )",
               R"({"t": 1, "p": [10, 10], "z": 25}, {"t": 4, "p": [20, 10]},
                  {"t": 6, "p": [30, 10], "z": 15})"),
      "profile.json");
  const UavSpec& uav = spec.uavs[0];
  ASSERT_TRUE(uav.altitude_profile.has_value());
  ASSERT_TRUE(uav.sensor.camera.has_value());  // a UAV at an altitude
  EXPECT_EQ(uav.body.z, 25.0);                 // the profile's at t = 0: its first point's, held
  EXPECT_EQ(uav.body.z_min, 15.0);
  EXPECT_EQ(uav.body.z_max, 25.0);
  EXPECT_EQ(uav.body.climb_rate, 3.0);
  // Linear in time between the points that give z: at 3.5 s, halfway from 25 m (1 s) to 15 m (6 s).
  EXPECT_DOUBLE_EQ(uav.altitude_profile->altitudeAt(3.5), 20.0);
  EXPECT_EQ(uav.altitude_profile->altitudeAt(9.0), 15.0);
  const ScenarioSpec again = loadScenarioText(spec.effective_config, "again.json");
  EXPECT_EQ(again.effective_config, spec.effective_config);
  EXPECT_EQ(again.uavs[0].altitude_profile->points().size(), 2u);
  EXPECT_EQ(again.uavs[0].body.z_min, 15.0);
  // A UAV's inline track rows may carry z too.
  const ScenarioSpec track = loadScenarioText(
      R"({"aoi": [0, 0, 100, 50], "uavs": [{"path": {"track": [[0, 10, 10, 30], [2, 12, 10, 34]]}}]})",
      "track.json");
  EXPECT_DOUBLE_EQ(track.uavs[0].altitude_profile->altitudeAt(1.0), 32.0);
  // Without any z the path makes no profile and the UAV keeps the paper's fixed footprint.
  const ScenarioSpec plain =
      loadScenarioText(scripted("", R"({"t": 0, "p": [10, 10]})"), "plain.json");
  EXPECT_FALSE(plain.uavs[0].altitude_profile.has_value());
  EXPECT_FALSE(plain.uavs[0].sensor.camera.has_value());
}

TEST(HeightFields, BadWaypointAltitudesAreRefusedNamingTheField) {
  const std::string outside = errorOf(
      scripted(R"("z": 20, "z_max": 30, )", R"({"t": 0, "p": [10, 10], "z": 31})"));
  EXPECT_NE(outside.find("uavs[0].path.waypoints[0].z"), std::string::npos) << outside;
  EXPECT_NE(outside.find("[z_min, z_max] = [20, 30]"), std::string::npos) << outside;
  EXPECT_NE(errorOf(scripted("", R"({"t": 0, "p": [10, 10], "z": -3})"))
                .find("uavs[0].path.waypoints[0].z"),
            std::string::npos);
  EXPECT_NE(errorOf(scripted("", R"({"t": 0, "p": [10, 10], "z": 2e4})"))
                .find("uavs[0].path.waypoints[0].z"),
            std::string::npos);
  EXPECT_NE(errorOf(scripted("", R"({"t": 0, "p": [10, 10], "z": "high"})"))
                .find("uavs[0].path.waypoints[0].z"),
            std::string::npos);
  // A climb rate of 0 cannot fly a changing altitude.
  const std::string stuck = errorOf(scripted(
      R"("climb_rate": 0, )", R"({"t": 0, "p": [10, 10], "z": 20}, {"t": 5, "p": [20, 10], "z": 30})"));
  EXPECT_NE(stuck.find("uavs[0].path.waypoints[1].z"), std::string::npos) << stuck;
  EXPECT_NE(stuck.find("climb_rate is 0"), std::string::npos) << stuck;
  // A ground robot's path has no altitude: an unknown field.
  EXPECT_NE(errorOf(scripted(R"("kind": "ground", )", R"({"t": 0, "p": [10, 10], "z": 1})"))
                .find("uavs[0].path.waypoints[0].z"),
            std::string::npos);
}

}  // namespace
}  // namespace canopy::spec
