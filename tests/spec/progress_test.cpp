// Long stages report how far they got (core/progress.h), counted here without a clock: a hook
// records every report of loading a scenario of N occluders and M targets, and the counts are
// those the reporting intervals give (start, every 4096 occluders / 1024 targets, end).
#include "core/progress.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "spec/loader.h"

namespace canopy {
namespace {

struct Report {
  std::string stage;
  double done, total;
};
std::vector<Report>& reports() {
  static std::vector<Report> all;
  return all;
}
void record(const char* stage, double done, double total) {
  reports().push_back({stage, done, total});
}

std::vector<Report> of(const std::string& stage) {
  std::vector<Report> out;
  for (const Report& r : reports())
    if (r.stage == stage) out.push_back(r);
  return out;
}

TEST(Progress, ThrottleIsDueFirstAfterItsDelayThenEveryInterval) {
  ProgressThrottle throttle(10.0, 2.0, 3.0);
  EXPECT_FALSE(throttle.due(11.9));
  EXPECT_TRUE(throttle.due(12.0));
  EXPECT_FALSE(throttle.due(14.9));
  EXPECT_TRUE(throttle.due(15.5));
  EXPECT_FALSE(throttle.due(18.4));
  EXPECT_TRUE(throttle.due(18.5));
}

TEST(Progress, LoadingReportsEachLongStageAtItsIntervals) {
  constexpr int kOccluders = 10000, kTargets = 3000;
  std::string text = R"({"aoi": [0, 0, 2000, 2000], "clock": {"dt": 1, "duration": 1},)"
                     R"( "uavs": [{"start": [1, 1], "fov": {"radius": 1}}], "occluders": [)";
  for (int i = 0; i < kOccluders; ++i) {
    text += (i ? "," : "") + std::string(R"({"type": "disc", "centre": [)") +
            std::to_string(10 + (i % 100) * 19) + ", " + std::to_string(10 + (i / 100) * 19) +
            R"(], "radius": 0.1})";
  }
  text += R"(], "targets": [)";
  for (int i = 0; i < kTargets; ++i) {
    text += (i ? "," : "") + std::string(R"({"path": {"start": [)") +
            std::to_string(5 + (i % 60) * 33) + ", " + std::to_string(5 + (i / 60) * 33) +
            R"(], "velocity": [0, 0]}})";
  }
  text += "]}";
  reports().clear();
  const ProgressHook before = setProgressHook(&record);
  spec::loadScenarioText(text, "progress.json");
  setProgressHook(before);

  // Occluders: the start, each 4096th (4096, 8192), the end.
  const std::vector<Report> occluders = of("reading occluders");
  ASSERT_EQ(occluders.size(), 4u);
  const std::vector<double> expected_done = {0, 4096, 8192, kOccluders};
  for (std::size_t i = 0; i < occluders.size(); ++i) {
    EXPECT_EQ(occluders[i].done, expected_done[i]);
    EXPECT_EQ(occluders[i].total, kOccluders);
  }
  // Targets: the start, 1024 and 2048, the end.
  const std::vector<Report> targets = of("reading targets");
  ASSERT_EQ(targets.size(), 4u);
  EXPECT_EQ(targets.back().done, kTargets);
  // The JSON's values: the root 1, aoi 5, clock 3, the UAV list 7; each disc 6 (its object,
  // "disc", the centre array and its two numbers, the radius), each target 8 (two objects, two
  // arrays of two numbers), each list 1 more: one report per 2^16 values.
  const double values = 1 + 5 + 3 + 7 + (1 + 6.0 * kOccluders) + (1 + 8.0 * kTargets);
  EXPECT_EQ(of("reading JSON (values)").size(), static_cast<std::size_t>(values / 65536));
  EXPECT_EQ(of("checking the work budget").size(), 1u);
  EXPECT_EQ(of("writing the effective configuration").size(), 1u);
}

TEST(Progress, WithoutAHookNothingIsCalled) {
  reports().clear();
  const ProgressHook before = setProgressHook(nullptr);
  { ProgressCounter counter("x", 10, 1); for (int i = 0; i < 10; ++i) counter.add(); }
  setProgressHook(before);
  EXPECT_TRUE(reports().empty());
}

}  // namespace
}  // namespace canopy
