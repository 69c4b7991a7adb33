#include "scenarios/run.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/text_file.h"
#include "scenarios/loader.h"
#include "scenarios/simulation.h"

namespace canopy::scenarios {
namespace {
namespace fs = std::filesystem;

std::string runAndRead(const std::string& scenario, std::uint64_t seed, const std::string& tag) {
  LoadOptions options;
  options.seed = seed;
  const ScenarioSpec spec = loadScenario(scenario, options);
  const fs::path dir = fs::temp_directory_path() / ("canopy_run_" + tag);
  fs::remove_all(dir);
  runScenario(spec, {dir, "test", {}});
  EXPECT_TRUE(fs::exists(dir / "manifest.json"));
  EXPECT_TRUE(fs::exists(dir / "summary.json"));
  return readTextFile(dir / "record.jsonl").value();
}

TEST(Run, SameSeedGivesByteIdenticalRecords) {
  const std::string a = runAndRead("demo", 5, "a");
  const std::string b = runAndRead("demo", 5, "b");
  const std::string c = runAndRead("demo", 6, "c");
  ASSERT_FALSE(a.empty());
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);  // the noise differs
}

TEST(Run, WritesOneRecordLinePerStepIncludingTheInitialState) {
  const ScenarioSpec spec = loadScenario("demo");
  const fs::path dir = fs::temp_directory_path() / "canopy_run_lines";
  const RunResult result = runScenario(spec, {dir, "test", {}});
  EXPECT_EQ(result.steps, spec.steps() + 1);
  std::ifstream in(dir / "record.jsonl");
  int lines = 0;
  for (std::string line; std::getline(in, line);) ++lines;
  EXPECT_EQ(lines, spec.steps() + 1);
}

TEST(Run, ScriptedUavsFollowTheirSweeps) {
  const ScenarioSpec spec = loadScenario("demo");
  Simulation sim(spec);
  while (!sim.done()) {
    const StepRecord& step = sim.tick();
    const double t = step.time;
    for (std::size_t i = 0; i < spec.uavs.size(); ++i) {
      // The sweeps never ask for more than v_max, so the UAVs are on their paths at every step.
      const Vec2 expected = spec.uavs[i].path->positionAt(t);
      EXPECT_NEAR((step.uavs[i].position - expected).norm(), 0.0, 1e-3)
          << "uav " << i << " t " << t;
    }
  }
}

}  // namespace
}  // namespace canopy::scenarios
