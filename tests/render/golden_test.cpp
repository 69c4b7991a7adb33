// Golden rendered coverage of the built-in scenarios, and frames written during a real run.
// The cases are data (tests/data/coverage_golden/cases.json); regenerate the CSVs deliberately
// with  CANOPY_UPDATE_GOLDENS=1 build/<dir>/tests/render/test_render_golden  (see README.md there).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>

#include "render/coverage.h"
#include "render/frame_writer.h"
#include "render/run_coverage.h"
#include "sim/run.h"
#include "sim/simulation.h"
#include "spec/loader.h"
#include "tests/render/golden_csv.h"

namespace canopy::render {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

const fs::path kGoldenDir = fs::path(CANOPY_SOURCE_DIR) / "tests" / "data" / "coverage_golden";

struct Case {
  std::string name;
  std::string scenario;
  ImageSize size;
  std::vector<std::string> overrides;
};

std::vector<Case> cases() {
  const Json json = Json::parse(std::ifstream(kGoldenDir / "cases.json"));
  std::vector<Case> out;
  for (const Json& c : json.at("cases")) {
    out.push_back({c.at("name"),
                   c.at("scenario"),
                   {c.at("size")[0], c.at("size")[1]},
                   c.at("set").get<std::vector<std::string>>()});
  }
  return out;
}

// The rendered coverage of every step of the run, as `canopy coverage` prints it: the run is
// written to a temporary folder and read back by the command's own code.
std::string coverageCsv(const Case& c) {
  spec::LoadOptions load;
  load.overrides = c.overrides;
  const spec::ScenarioSpec spec = spec::loadScenario(c.scenario, load);
  const fs::path dir =
      fs::temp_directory_path() / ("canopy_golden_" + c.name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  sim::RunOptions options;
  options.out_dir = dir;
  sim::runScenario(spec, options);
  std::string csv = render::coverageCsvOfRun(dir, c.size);
  fs::remove_all(dir);
  return csv;
}

TEST(CoverageGolden, BuiltInScenariosMatchTheirGoldenFiles) {
  const bool update = std::getenv("CANOPY_UPDATE_GOLDENS") != nullptr;
  const std::vector<Case> list = cases();
  ASSERT_FALSE(list.empty());
  for (const Case& c : list) {
    const fs::path golden = kGoldenDir / (c.name + ".csv");
    const std::string actual = coverageCsv(c);
    if (update) {
      std::ofstream(golden, std::ios::binary | std::ios::trunc) << actual;
      std::printf("updated %s\n", golden.c_str());
      continue;
    }
    ASSERT_TRUE(fs::exists(golden))
        << golden << " is missing; regenerate with CANOPY_UPDATE_GOLDENS=1";
    EXPECT_EQ(testing::compareCoverageCsv(testing::readFile(golden.string()), actual), "")
        << c.name;
  }
}

TEST(CoverageGolden, DemoCoversSomethingEveryStep) {
  // A sanity check on the golden data itself: both UAVs always see some of the AOI.
  const auto rows = testing::parseCsv(testing::readFile((kGoldenDir / "demo.csv").string()));
  ASSERT_GT(rows.size(), 100u);
  for (std::size_t i = 1; i < rows.size(); ++i) EXPECT_GT(std::atol(rows[i][2].c_str()), 0) << i;
}

TEST(RunFrames, ARunWithFramesUsesOneGlContextAndARunWithoutNone) {
  spec::LoadOptions load;
  load.overrides = {"clock.duration=4"};
  const spec::ScenarioSpec spec = spec::loadScenario("demo", load);
  const fs::path dir =
      fs::temp_directory_path() / ("canopy_run_frames_" + std::to_string(::getpid()));
  fs::remove_all(dir);

  const int before = glContextsCreated();
  sim::RunOptions plain;
  plain.out_dir = dir / "plain";
  sim::runScenario(spec, plain);
  EXPECT_EQ(glContextsCreated(), before);

  SceneModel model;
  model.aoi = spec.aoi;
  model.trees = spec.trees;
  for (const spec::UavSpec& uav : spec.uavs) model.sensors.push_back(uav.sensor);
  FrameOptions frames;
  frames.dir = dir / "framed" / "frames";
  frames.every = 5;
  frames.size = {240, 160};
  FrameWriter writer(model, frames);
  sim::RunOptions framed;
  framed.out_dir = dir / "framed";
  struct Frames final : sim::StepObserver {
    FrameWriter& writer;
    explicit Frames(FrameWriter& w) : writer(w) {}
    void onStep(const sim::StepRecord& record) override {
      world::WorldSnapshot truth;
      sim::truthSnapshot(record, truth);
      writer.onStep(truth, record.beliefs);
    }
  } frames_observer(writer);
  framed.observers = {&frames_observer};
  sim::runScenario(spec, framed);
  EXPECT_EQ(glContextsCreated(), before + 1);
  EXPECT_EQ(writer.framesWritten(), 5);  // steps 0, 5, 10, 15, 20 of 0..20
  EXPECT_TRUE(fs::exists(dir / "framed" / "frames" / "frame_000020.png"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace canopy::render
