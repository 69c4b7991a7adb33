// The record reader against the simulation that wrote the record: the truth it reads back is the
// truth the simulation held at every step (written with %.17g-exact doubles, so equal to the bit),
// and every way a run folder can be wrong is an error naming the file, the line and the field.
#include "sim/record_reader.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/text_file.h"
#include "sim/run.h"
#include "sim/simulation.h"
#include "spec/error.h"
#include "spec/loader.h"

namespace canopy::sim {
namespace {
namespace fs = std::filesystem;

fs::path freshDir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("canopy_record_reader_" + name);
  fs::remove_all(dir);
  return dir;
}

spec::ScenarioSpec shortDemo() {
  spec::LoadOptions options;
  options.seed = 5;
  options.overrides = {"clock.duration=2"};
  return spec::loadScenario("demo", options);
}

TEST(RecordReader, ReadsBackTheTruthTheSimulationHeld) {
  const spec::ScenarioSpec spec = shortDemo();
  const fs::path dir = freshDir("truth");
  runScenario(spec, {dir, "test", {}});

  Simulation sim(spec);  // the same seed: the same run, step by step
  const RunRecord run = readRun(dir);
  ASSERT_EQ(run.truth.size(), static_cast<std::size_t>(spec.steps()) + 1);  // k = 0 … steps
  ASSERT_EQ(run.spec.uavs.size(), spec.uavs.size());
  for (const world::WorldSnapshot& read : run.truth) {
    const StepRecord& step = sim.tick();
    EXPECT_EQ(read.step, step.step);
    EXPECT_EQ(read.time, step.time);
    for (std::size_t i = 0; i < spec.uavs.size(); ++i) {
      EXPECT_EQ(read.uavs[i].position, step.uavs[i].position) << "step " << step.step;
      EXPECT_EQ(read.uavs[i].yaw, step.uavs[i].yaw);
    }
    for (std::size_t t = 0; t < spec.targets.size(); ++t) {
      EXPECT_EQ(read.targets[t].position, step.targets[t].position) << "step " << step.step;
    }
  }
}

std::string errorOf(const fs::path& dir) {
  try {
    readRun(dir);
  } catch (const spec::ScenarioError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(RecordReader, NamesTheFileLineAndFieldOfEveryFault) {
  const fs::path dir = freshDir("faults");
  EXPECT_NE(errorOf(dir).find("no such directory"), std::string::npos);
  runScenario(shortDemo(), {dir, "test", {}});
  const std::string record = readTextFile(dir / "record.jsonl").value();
  const std::string first = record.substr(0, record.find('\n') + 1);

  std::ofstream(dir / "record.jsonl") << first << "{\"k\": 1, \"t\": 0.2, \"targets\": []}\n";
  EXPECT_NE(errorOf(dir).find("record.jsonl: line 2: uavs: expected a field 'uavs'"),
            std::string::npos)
      << errorOf(dir);
  std::ofstream(dir / "record.jsonl") << first << std::string(100000, '[') << "\n";
  EXPECT_NE(errorOf(dir).find("record.jsonl: line 2: expected one JSON object per line, nested"),
            std::string::npos)
      << errorOf(dir);
  std::ofstream(dir / "record.jsonl") << "";
  EXPECT_NE(errorOf(dir).find("record.jsonl: has no steps"), std::string::npos);

  // A manifest nested 100 000 deep is refused by its depth, not by the stack.
  std::ofstream(dir / "manifest.json") << std::string(100000, '[');
  EXPECT_NE(errorOf(dir).find("manifest.json: expected JSON nested at most 64 levels"),
            std::string::npos)
      << errorOf(dir);
  fs::remove(dir / "manifest.json");
  fs::create_directory(dir / "manifest.json");
  EXPECT_NE(errorOf(dir).find("manifest.json: is a directory, expected the manifest"),
            std::string::npos)
      << errorOf(dir);
}

}  // namespace
}  // namespace canopy::sim
