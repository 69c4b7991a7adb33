#include "sim/run.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/random.h"
#include "core/text_file.h"
#include "sim/simulation.h"
#include "spec/loader.h"

namespace canopy::sim {
namespace {
namespace fs = std::filesystem;

std::string runAndRead(const std::string& scenario, std::uint64_t seed, const std::string& tag) {
  spec::LoadOptions options;
  options.seed = seed;
  const spec::ScenarioSpec spec = spec::loadScenario(scenario, options);
  const fs::path dir = fs::temp_directory_path() / ("canopy_run_" + tag);
  fs::remove_all(dir);
  runScenario(spec, {dir, "test", {}});
  EXPECT_TRUE(fs::exists(dir / "manifest.json"));
  EXPECT_TRUE(fs::exists(dir / "summary.json"));
  return readTextFile(dir / "record.jsonl").value();
}

// The manifest splices the effective configuration's text in; the same bytes as parsing it and
// dumping the whole manifest (the way it was written before), for every library scenario and
// command lines that try to look like the spliced key or are not UTF-8.
TEST(Run, ManifestEqualsTheParsedAndDumpedConfiguration) {
  using Json = nlohmann::json;
  const std::vector<std::string> commands = {
      "canopy run demo", "say \"effective_config\": \"spliced: the effective configuration\"",
      "two\n  \"effective_config\": lines", std::string("bytes \xff\xfe not UTF-8"), ""};
  int compared = 0;
  for (const std::string& name : spec::libraryScenarios()) {
    const spec::ScenarioSpec spec = spec::loadScenario(name);
    for (const std::string& command : commands) {
      char hash[17];
      std::snprintf(hash, sizeof hash, "%016llx",
                    static_cast<unsigned long long>(fnv1a64(spec.effective_config)));
      Json manifest = Json::parse(manifestJson(spec, command));
      EXPECT_EQ(manifest.at("config_hash_fnv1a64").get<std::string>(), std::string(hash));
      Json expected = manifest;
      expected["effective_config"] = Json::parse(spec.effective_config);
      // Re-dumped from the parsed manifest the two agree, and the text itself is that dump.
      EXPECT_EQ(manifestJson(spec, command),
                expected.dump(2, ' ', false, Json::error_handler_t::replace))
          << name << " / " << command;
      ++compared;
    }
  }
  EXPECT_GE(compared, 5 * 10);
}

// A rerun into the folder of a run with frames, without frames, leaves no frame of the old run
// beside the new record (what else is in frames/ is not the run's and stays).
TEST(Run, StaleFramesOfAnEarlierRunAreRemoved) {
  const fs::path dir = fs::temp_directory_path() / "canopy_run_stale_frames";
  fs::remove_all(dir);
  fs::create_directories(dir / "frames");
  for (const char* name : {"frame_000000.png", "frame_000004.png", "notes.txt"})
    std::ofstream(dir / "frames" / name) << "old";
  spec::LoadOptions options;
  options.overrides = {"clock.duration=1"};
  runScenario(spec::loadScenario("demo", options), {dir, "test", {}});
  EXPECT_FALSE(fs::exists(dir / "frames" / "frame_000000.png"));
  EXPECT_FALSE(fs::exists(dir / "frames" / "frame_000004.png"));
  EXPECT_TRUE(fs::exists(dir / "frames" / "notes.txt"));
  EXPECT_TRUE(fs::exists(dir / "record.jsonl"));
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
  const spec::ScenarioSpec spec = spec::loadScenario("demo");
  const fs::path dir = fs::temp_directory_path() / "canopy_run_lines";
  const RunResult result = runScenario(spec, {dir, "test", {}});
  EXPECT_EQ(result.steps, spec.steps() + 1);
  std::ifstream in(dir / "record.jsonl");
  int lines = 0;
  for (std::string line; std::getline(in, line);) ++lines;
  EXPECT_EQ(lines, spec.steps() + 1);
}

TEST(Run, ScriptedUavsFollowTheirSweeps) {
  const spec::ScenarioSpec spec = spec::loadScenario("demo");
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
}  // namespace canopy::sim
