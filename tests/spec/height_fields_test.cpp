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

}  // namespace
}  // namespace canopy::spec
