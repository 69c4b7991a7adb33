// Issue 53's bar on a scenario of our own: two UAVs hovering at fixed altitudes 20 m and 40 m with
// the same camera. The rendered coverage of the higher one, counted from its recorded altitude as
// `canopy coverage` counts it, is 4 × ± 5 % the lower one's (the closed form gives exactly 4);
// the measurement covariances it records are larger.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "core/text_file.h"
#include "render/coverage.h"
#include "render/frame_writer.h"
#include "render/run_coverage.h"
#include "sim/record_reader.h"
#include "sim/run.h"
#include "spec/loader.h"

namespace canopy::render {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

// Two UAVs 100 m apart (footprints 20 × 14 m at 20 m and 40 × 28 m at 40 m: apart), each over a
// standing walker 3 m east and 4 m north of its ground point, no trees.
constexpr const char* kTwoAltitudes = R"({
  "name": "two_altitudes",
  "aoi": [0, 0, 200, 100],
  "clock": {"dt": 0.5, "duration": 10},
  "seed": 5,
  "uavs": [
    {"name": "low", "start": [50, 50], "fov": {"size": [20, 14]}, "z": 20},
    {"name": "high", "start": [150, 50], "fov": {"size": [20, 14]}, "z": 40}
  ],
  "targets": [
    {"name": "A", "path": {"start": [53, 54], "velocity": [0, 0]}},
    {"name": "B", "path": {"start": [153, 54], "velocity": [0, 0]}}
  ]
})";

struct TempDir {
  fs::path path = fs::temp_directory_path() / ("canopy_height_" + std::to_string(::getpid()));
  TempDir() { fs::create_directories(path); }
  ~TempDir() { fs::remove_all(path); }
};

TEST(HeightBar, HigherUavCoversFourTimesAndMeasuresWorse) {
  const TempDir dir;
  const fs::path scenario = dir.path / "two_altitudes.json";
  std::ofstream(scenario) << kTwoAltitudes;
  const spec::ScenarioSpec spec = spec::loadScenario(scenario.string());
  sim::RunOptions options;
  options.out_dir = dir.path / "run";
  sim::runScenario(spec, options);

  // Rendered coverage, from the record and the manifest as `canopy coverage` reads them: each
  // UAV's footprint alone, and the team's (both) through coverageCsvOfRun itself.
  const sim::RunRecord run = sim::readRun(options.out_dir);
  ASSERT_FALSE(run.truth.empty());
  CoverageCounter counter(run.spec.aoi, fitSize(run.spec.aoi, kDefaultFrameLongSide));
  const world::WorldSnapshot& last = run.truth.back();
  EXPECT_DOUBLE_EQ(last.uavs[0].z, 20.0);
  EXPECT_DOUBLE_EQ(last.uavs[1].z, 40.0);
  const sensing::Footprint low = sensing::footprintOf(last, 0, run.spec.uavs[0].sensor);
  const sensing::Footprint high = sensing::footprintOf(last, 1, run.spec.uavs[1].sensor);
  const std::vector<Vec2> none;
  const long low_px = counter.count(std::span(&low, 1), none).covered_px;
  const long high_px = counter.count(std::span(&high, 1), none).covered_px;
  ASSERT_GT(low_px, 100);
  const double ratio = static_cast<double>(high_px) / static_cast<double>(low_px);
  EXPECT_NEAR(ratio, 4.0, 0.2) << low_px << " px against " << high_px << " px";
  // The pixel counts approach the closed-form areas 20·14 and 40·28 m².
  EXPECT_NEAR(static_cast<double>(low_px) * counter.pixelArea(), 280.0, 0.05 * 280.0);
  EXPECT_NEAR(static_cast<double>(high_px) * counter.pixelArea(), 1120.0, 0.05 * 1120.0);

  const std::string csv = coverageCsvOfRun(options.out_dir);
  std::istringstream lines(csv);
  std::string header, row;
  std::getline(lines, header);
  std::getline(lines, row);  // step 0: step,t,covered_px,…
  std::istringstream cells(row);
  std::string step, t, covered;
  std::getline(cells, step, ',');
  std::getline(cells, t, ',');
  std::getline(cells, covered, ',');
  EXPECT_EQ(std::stol(covered), low_px + high_px);

  // The record: "z" in each UAV's entry, and the higher UAV's measurement covariances larger.
  const std::optional<std::string> record = readTextFile(options.out_dir / "record.jsonl");
  ASSERT_TRUE(record);
  std::istringstream steps(*record);
  std::string line;
  int compared = 0;
  while (std::getline(steps, line)) {
    const Json j = Json::parse(line);
    EXPECT_DOUBLE_EQ(j["uavs"][0]["z"].get<double>(), 20.0);
    EXPECT_DOUBLE_EQ(j["uavs"][1]["z"].get<double>(), 40.0);
    double trace[2] = {0.0, 0.0};
    int seen[2] = {0, 0};
    for (const Json& scan : j["scans"]) {
      const int uav = scan["uav"].get<int>();
      for (const Json& obs : scan["obs"]) {
        if (obs["label"] != "human") continue;
        const Json& R = obs["R"];  // upper triangle [xx, xy, yy]
        trace[uav] += R[0].get<double>() + R[2].get<double>();
        ++seen[uav];
      }
    }
    ASSERT_EQ(seen[0], 1);
    ASSERT_EQ(seen[1], 1);
    EXPECT_GT(trace[1], trace[0]);
    ++compared;
  }
  EXPECT_EQ(compared, 21);
}

TEST(HeightBar, AltitudeTradeoffRunsAndItsUavsChangeAltitude) {
  // The built-in scenario, its first 12 s: the people walk apart and the planner's climbs move
  // both UAVs off their start altitude of 20 m, within [10, 60] m, at most 2 m/s.
  const TempDir dir;
  spec::LoadOptions load;
  load.overrides = {"clock.duration=12"};
  const spec::ScenarioSpec spec = spec::loadScenario("altitude_tradeoff", load);
  sim::RunOptions options;
  options.out_dir = dir.path / "run";
  sim::runScenario(spec, options);
  const std::optional<std::string> record = readTextFile(options.out_dir / "record.jsonl");
  ASSERT_TRUE(record);
  std::istringstream steps(*record);
  std::string line;
  double previous[2] = {20.0, 20.0}, lowest[2] = {1e9, 1e9}, highest[2] = {0.0, 0.0};
  while (std::getline(steps, line)) {
    const Json j = Json::parse(line);
    for (int i = 0; i < 2; ++i) {
      const double z = j["uavs"][i]["z"].get<double>();
      EXPECT_LE(std::abs(z - previous[i]), 2.0 * spec.dt + 1e-9);  // |ż| ≤ climb_rate
      EXPECT_GE(z, 10.0);
      EXPECT_LE(z, 60.0);
      lowest[i] = std::min(lowest[i], z);
      highest[i] = std::max(highest[i], z);
      previous[i] = z;
    }
  }
  for (int i = 0; i < 2; ++i) EXPECT_GT(highest[i] - lowest[i], 2.0) << "UAV " << i;
}

TEST(HeightBar, ScenarioWithoutAltitudeRecordsNoZ) {
  const TempDir dir;
  const fs::path scenario = dir.path / "flat.json";
  Json flat = Json::parse(kTwoAltitudes);
  for (Json& uav : flat["uavs"]) uav.erase("z");
  std::ofstream(scenario) << flat.dump();
  sim::RunOptions options;
  options.out_dir = dir.path / "run";
  sim::runScenario(spec::loadScenario(scenario.string()), options);
  const std::optional<std::string> record = readTextFile(options.out_dir / "record.jsonl");
  ASSERT_TRUE(record);
  std::istringstream steps(*record);
  std::string line;
  int lines = 0;
  while (std::getline(steps, line)) {
    const Json j = Json::parse(line);
    for (const Json& uav : j["uavs"]) EXPECT_FALSE(uav.contains("z"));
    ++lines;
  }
  EXPECT_EQ(lines, 21);
}

}  // namespace
}  // namespace canopy::render
