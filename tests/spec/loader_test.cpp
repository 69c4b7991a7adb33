#include "spec/loader.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "agents/config.h"
#include "core/random.h"
#include "spec/error.h"

namespace canopy::spec {
namespace {
namespace fs = std::filesystem;

constexpr const char* kMinimal = R"({
  // comments are allowed
  "aoi": [0, 0, 100, 50],
  "uavs": [{"start": [10, 10]}],
  "targets": [{"path": {"start": [20, 20], "velocity": [1, 0]}}]
})";

TEST(Loader, FillsEveryDefaultOfAlgorithmsMd) {
  const ScenarioSpec spec = loadScenarioText(kMinimal, "minimal.json");
  EXPECT_EQ(spec.name, "minimal");
  EXPECT_DOUBLE_EQ(spec.dt, 0.2);
  EXPECT_EQ(spec.steps(), 100);  // 20 s of 0.2 s
  ASSERT_EQ(spec.uavs.size(), 1u);
  EXPECT_EQ(spec.uavs[0].name, "uav1");
  EXPECT_DOUBLE_EQ(spec.uavs[0].body.v_max, 5.0);
  EXPECT_EQ(spec.uavs[0].sensor.footprint.size, Vec2(20, 20));
  EXPECT_DOUBLE_EQ(spec.uavs[0].sensor.quality.alpha, 0.3);
  EXPECT_DOUBLE_EQ(spec.uavs[0].sensor.quality.r0, 2.0);
  EXPECT_EQ(spec.labels, (std::vector<std::string>{"tree", "human"}));
  EXPECT_EQ(spec.targets[0].label, 1);
  EXPECT_EQ(spec.sensing.occlusion_model, sensing::OcclusionModel::canopy);
  EXPECT_DOUBLE_EQ(spec.sensing.p_detect, 1.0);
  EXPECT_DOUBLE_EQ(spec.tracking.gate_probability, 0.98);
  EXPECT_DOUBLE_EQ(spec.tracking.delete_trace, 400.0);
  EXPECT_EQ(spec.fusion.method, agents::FusionMethod::ci);
  EXPECT_EQ(spec.fusion.rounds, 5);
  EXPECT_EQ(spec.planner.algorithm, agents::PlannerAlgorithm::none);
  EXPECT_EQ(spec.planner.pso.particles_per_step, 20);
  EXPECT_DOUBLE_EQ(spec.planner.pso.inertia, 0.9);
  EXPECT_EQ(spec.planner.order, (std::vector<int>{0}));
  EXPECT_EQ(spec.analysis.m, 5);
}

TEST(Loader, EffectiveConfigSpellsEveryEnumDefaultOfAlgorithmsMd) {
  // The spellings algorithms.md gives for the defaults, written here by hand.
  const ScenarioSpec spec = loadScenarioText(kMinimal, "minimal.json");
  const nlohmann::json config = nlohmann::json::parse(spec.effective_config);
  EXPECT_EQ(config["sensing"]["occlusion_model"], "canopy");
  EXPECT_EQ(config["fusion"]["method"], "ci");
  EXPECT_EQ(config["planner"]["algorithm"], "none");
  EXPECT_EQ(config["planner"]["occlusion_map"], "dynamic");
  // Dec-POMDP's joint search departs from the paper's one swarm (docs/design-notes.md).
  EXPECT_EQ(config["planner"]["joint_search"], "block_coordinate");
  EXPECT_EQ(config["planner"]["cost_trace"], "position");
  EXPECT_EQ(config["uavs"][0]["fov"]["size"], nlohmann::json({20.0, 20.0}));
}

TEST(Loader, ReadsEverySpellingOfEachEnum) {
  for (const auto& [value, name] : agents::kOcclusionMapModeNames) {
    LoadOptions options;
    options.overrides = {"planner.occlusion_map=\"" + std::string(name) + "\""};
    EXPECT_EQ(loadScenarioText(kMinimal, "minimal.json", options).planner.occlusion_map, value);
  }
  for (const auto& [value, name] : agents::kFusionMethodNames) {
    LoadOptions options;
    options.overrides = {"fusion.method=\"" + std::string(name) + "\""};
    EXPECT_EQ(loadScenarioText(kMinimal, "minimal.json", options).fusion.method, value);
  }
}

TEST(Loader, EffectiveConfigReloadsToTheSameConfig) {
  const ScenarioSpec spec = loadScenario("demo");
  const ScenarioSpec again = loadScenarioText(spec.effective_config, spec.file.string());
  EXPECT_EQ(again.effective_config, spec.effective_config);
  EXPECT_EQ(again.trees.size(), spec.trees.size());
  for (std::size_t k = 0; k < spec.trees.size(); ++k)
    EXPECT_EQ(again.trees[k].centre, spec.trees[k].centre);
}

TEST(Loader, OverridesEditDottedPathsBeforeValidation) {
  LoadOptions options;
  options.overrides = {"planner.horizon=1", "uavs.0.v_max=3.5", "planner.algorithm=sma",
                       "fusion.comm_range=null", "sensing.occlusion_model=\"line_of_sight\""};
  options.seed = 99;
  const ScenarioSpec spec = loadScenarioText(kMinimal, "minimal.json", options);
  EXPECT_EQ(spec.planner.horizon, 1);
  EXPECT_DOUBLE_EQ(spec.uavs[0].body.v_max, 3.5);
  EXPECT_EQ(spec.planner.algorithm, agents::PlannerAlgorithm::sma);
  EXPECT_TRUE(std::isinf(spec.fusion.comm_range));
  EXPECT_EQ(spec.sensing.occlusion_model, sensing::OcclusionModel::line_of_sight);
  EXPECT_EQ(spec.seed, 99u);
}

TEST(Loader, LabelsAreNumberedInOrderOfFirstUse) {
  const std::string text = R"({
    "aoi": [0, 0, 100, 100], "uavs": [{"start": [1, 1]}],
    "sensing": {"clutter_label": "dog"},
    "targets": [
      {"label": "car", "path": {"start": [5, 5], "velocity": [0, 0]}},
      {"label": "human", "path": {"start": [6, 5], "velocity": [0, 0]}},
      {"label": "car", "path": {"start": [7, 5], "velocity": [0, 0]}}]})";
  const ScenarioSpec spec = loadScenarioText(text, "labels.json");
  EXPECT_EQ(spec.labels, (std::vector<std::string>{"tree", "car", "human", "dog"}));
  EXPECT_EQ(spec.targetLabels(), (std::vector<sensing::LabelId>{1, 2, 1}));
  EXPECT_EQ(spec.sensing.clutter_label, 3);
}

TEST(Loader, UavStartDefaultsToItsScriptedPath) {
  const std::string text = R"({"aoi": [0, 0, 100, 100],
    "uavs": [{"yaw": "velocity", "fov": {"radius": 7},
              "path": {"waypoints": [{"t": 1, "p": [10, 20]}, {"t": 5, "p": [30, 20]}]}}]})";
  const ScenarioSpec spec = loadScenarioText(text, "sweep.json");
  EXPECT_EQ(spec.uavs[0].body.start, Vec2(10, 20));
  EXPECT_EQ(spec.uavs[0].body.yaw_mode, world::YawMode::velocity);
  EXPECT_EQ(spec.uavs[0].sensor.footprint.shape, sensing::FootprintShape::disc);
}

TEST(Loader, LayoutIncludesResolveBesideTheFileAndNest) {
  const fs::path dir = fs::temp_directory_path() / "canopy_loader_include";
  fs::create_directories(dir / "layouts");
  std::ofstream(dir / "layouts" / "inner.json")
      << R"([{"type": "disc", "centre": [50, 50], "radius": 2}])";
  std::ofstream(dir / "layouts" / "outer.json")
      << R"({"description": "x", "occluders": [{"include": "inner.json"},
             {"type": "disc", "centre": [60, 50], "radius": 1}]})";
  std::ofstream(dir / "scenario.json") << R"({"aoi": [0, 0, 100, 100], "uavs": [{"start": [1, 1]}],
      "occluders": [{"include": "layouts/outer.json"}, {"include": "layouts/inner.json"}]})";
  const ScenarioSpec spec = loadScenario((dir / "scenario.json").string());
  ASSERT_EQ(spec.trees.size(), 3u);
  EXPECT_EQ(spec.trees[1].centre, Vec2(60, 50));
  EXPECT_EQ(loadLayout((dir / "layouts" / "outer.json").string()).size(), 2u);
}

TEST(Loader, TrackFilesAreReadAsTimedPoints) {
  const fs::path dir = fs::temp_directory_path() / "canopy_loader_track";
  fs::create_directories(dir);
  std::ofstream(dir / "walk.csv") << "t,x,y\n0,10,10\n# a pause\n2,14,10\n4,14,18\n";
  std::ofstream(dir / "scenario.json") << R"({"aoi": [0, 0, 100, 100], "uavs": [{"start": [1, 1]}],
      "targets": [{"path": {"track": "walk.csv"}}]})";
  const ScenarioSpec spec = loadScenario((dir / "scenario.json").string());
  EXPECT_EQ(spec.targets[0].path.positionAt(1.0), Vec2(12, 10));
  EXPECT_EQ(spec.targets[0].path.positionAt(3.0), Vec2(14, 14));
}

TEST(Loader, TheLibraryHoldsTheDemo) {
  const std::vector<std::string> names = libraryScenarios();
  EXPECT_NE(std::find(names.begin(), names.end(), "demo"), names.end());
  const ScenarioSpec demo = loadScenario("demo");
  EXPECT_EQ(demo.uavs.size(), 2u);
  EXPECT_EQ(demo.targets.size(), 3u);
  EXPECT_GE(demo.trees.size(), 3u);
}

// Whatever bytes a file holds, loading ends in a spec or a ScenarioError — never another
// exception, a crash or a hang (run under the sanitizer preset in CI).
TEST(Loader, MutatedFilesFailCleanly) {
  const std::string text = loadScenario("demo").effective_config;
  RandomStream rng(2024, "mutation");
  int rejected = 0;
  for (int trial = 0; trial < 400; ++trial) {
    std::string mutated = text;
    const int edits = 1 + static_cast<int>(rng.uniform() * 3);
    for (int e = 0; e < edits; ++e) {
      const std::size_t at =
          static_cast<std::size_t>(rng.uniform() * static_cast<double>(mutated.size()));
      const char replacement = "0-9e.,:[]{}\" -aZ"[static_cast<int>(rng.uniform() * 17)];
      if (rng.bernoulli(0.5)) {
        mutated[at] = replacement;
      } else {
        mutated.erase(at, 1);
      }
    }
    try {
      loadScenarioText(mutated, "mutated.json");
    } catch (const ScenarioError&) {
      ++rejected;
    }
  }
  EXPECT_GT(rejected, 100);
}

// CANOPY_PATH's folders come before the built-in library, in order; CANOPY_LIBRARY_DIR adds a
// folder after them instead of replacing the library.
TEST(ScenarioSearchPath, CanopyPathComesFirstAndTheLibraryStays) {
  const fs::path root = fs::temp_directory_path() / ("canopy_path_" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::create_directories(root / "a");
  fs::create_directories(root / "b");
  fs::create_directories(root / "c");
  const std::string scenario =
      R"({"description": "DESC", "aoi": [0, 0, 10, 10], "uavs": [{"start": [1, 1]}]})";
  auto write = [&](const fs::path& file, const std::string& description) {
    std::string text = scenario;
    text.replace(text.find("DESC"), 4, description);
    std::ofstream(file) << text;
  };
  write(root / "a" / "demo.json", "my demo");
  write(root / "b" / "demo.json", "second demo");
  write(root / "b" / "mine.json", "mine");
  write(root / "c" / "extra.json", "extra");
  ::setenv("CANOPY_PATH", ((root / "a").string() + ":" + (root / "b").string()).c_str(), 1);
  ::setenv("CANOPY_LIBRARY_DIR", (root / "c").c_str(), 1);

  EXPECT_EQ(resolveScenario("demo"), root / "a" / "demo.json");
  EXPECT_EQ(loadScenario("demo").description, "my demo");
  EXPECT_EQ(resolveScenario("mine"), root / "b" / "mine.json");
  EXPECT_EQ(resolveScenario("extra"), root / "c" / "extra.json");
  EXPECT_EQ(resolveScenario("joint_effect"), libraryDir() / "joint_effect.json");
  const std::vector<std::string> names = libraryScenarios();
  for (const char* name : {"demo", "mine", "extra", "joint_effect"})
    EXPECT_EQ(std::count(names.begin(), names.end(), name), 1) << name;
  EXPECT_EQ(scenarioSearchPath(),
            (std::vector<fs::path>{root / "a", root / "b", root / "c", libraryDir()}));

  ::unsetenv("CANOPY_PATH");
  ::unsetenv("CANOPY_LIBRARY_DIR");
  EXPECT_EQ(resolveScenario("demo"), libraryDir() / "demo.json");
  EXPECT_THROW(resolveScenario("mine"), ScenarioError);
  fs::remove_all(root);
}

}  // namespace
}  // namespace canopy::spec
