// Issue 47: no NaN reaches an output. A step whose state is not finite stops the run with
// NonFiniteState naming the step, the body and the quantity, and `canopy run` (runScenario)
// leaves none of its files. The NaN is put where the loader would never let it: into the
// loaded spec's scripted paths.
#include "sim/finite_check.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <string>

#include "sim/run.h"
#include "sim/simulation.h"
#include "spec/loader.h"

namespace canopy::sim {
namespace {
namespace fs = std::filesystem;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// dt = 0.2 s, one UAV following a path, one target on a path; no planner.
spec::ScenarioSpec scene() {
  return spec::loadScenarioText(
      R"({"aoi": [-50, -50, 50, 50], "clock": {"dt": 0.2, "duration": 4},
          "planner": {"algorithm": "none"},
          "uavs": [{"name": "scout", "start": [0, 0],
                    "path": {"waypoints": [{"t": 0, "p": [0, 0]}, {"t": 4, "p": [10, 0]}]}}],
          "targets": [{"path": {"start": [5, 5], "velocity": [1, 0]}}]})",
      "finite_check_test.json");
}

// Still at the origin until t = 0.5 s, then towards a NaN knot at t = 10 s: every position from
// t = 0.5 s on is NaN (0 × NaN is NaN), so the first step k with k·dt ≥ 0.5 s, k = 3 at
// dt = 0.2 s, is the first that holds one.
world::Path nanAfterHalfASecond() {
  return world::Path::throughPoints({{0.0, Vec2(0, 0)}, {0.5, Vec2(0, 0)}, {10.0, Vec2(kNaN, 0)}});
}

std::string stopMessage(Simulation& sim) {
  try {
    while (!sim.done()) sim.tick();
  } catch (const NonFiniteState& e) {
    return e.what();
  }
  return "";
}

TEST(FiniteCheck, ATargetTheWorldMovesToNaNStopsTheRunAtThatStep) {
  spec::ScenarioSpec spec = scene();
  spec.targets[0].path = nanAfterHalfASecond();
  Simulation sim(spec);
  const std::string message = stopMessage(sim);
  EXPECT_NE(message.find("step 3: target 0 position is not finite (nan"), std::string::npos)
      << message;
  EXPECT_NE(message.find("the world's step"), std::string::npos) << message;
  EXPECT_EQ(sim.nextStep(), 3);  // steps 0..2 ran, step 3 did not complete
}

TEST(FiniteCheck, ANaNCommandStopsTheRunBeforeTheWorldFliesIt) {
  // The path is aimed at one step ahead (t + dt): at step 2 (t = 0.4 s) the aim is t = 0.6 s.
  spec::ScenarioSpec spec = scene();
  spec.uavs[0].path = nanAfterHalfASecond();
  Simulation sim(spec);
  const std::string message = stopMessage(sim);
  EXPECT_NE(message.find("step 2: agent 0 (scout) command is not finite"), std::string::npos)
      << message;
}

TEST(FiniteCheck, ARunThatMeetsNaNLeavesNoFiles) {
  spec::ScenarioSpec spec = scene();
  spec.targets[0].path = nanAfterHalfASecond();
  const fs::path dir = fs::temp_directory_path() / "canopy_finite_check_run";
  fs::remove_all(dir);
  EXPECT_THROW(runScenario(spec, {dir, "test", {}}), NonFiniteState);
  ASSERT_TRUE(fs::is_directory(dir));
  EXPECT_TRUE(fs::is_empty(dir)) << "a failed run left files in " << dir;
  fs::remove_all(dir);
}

TEST(FiniteCheck, AFiniteRunIsUntouched) {
  Simulation sim(scene());
  EXPECT_EQ(stopMessage(sim), "");
  EXPECT_TRUE(sim.done());
}

}  // namespace
}  // namespace canopy::sim
