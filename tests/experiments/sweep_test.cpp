#include "experiments/sweep.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>

#include "core/text_file.h"
#include "spec/error.h"

namespace canopy::experiments {
namespace {
namespace fs = std::filesystem;

constexpr const char* kSweep = R"({
  "name": "small",
  "scenario": "demo",
  "trials": 3,
  "seed": 7,
  "set": {"clock.duration": 4.0},
  "axes": [{"path": "sensing.p_detect", "values": [1.0, 0.5]},
           {"path": "sensing.occlusion_model", "values": ["canopy", "line_of_sight"]}]
})";

// Every trial file of a sweep directory, by relative path.
// The trial files, without the temporaries a killed writer leaves behind (never read back).
std::map<std::string, std::string> trialFiles(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(dir / "trials")) {
    if (entry.is_regular_file() && entry.path().extension() != ".tmp")
      files[fs::relative(entry.path(), dir).string()] = readTextFile(entry.path()).value();
  }
  return files;
}

fs::path freshDir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("canopy_sweep_" + name);
  fs::remove_all(dir);
  return dir;
}

// Trial t of configuration c is number c·T + t; shard I of N owns the numbers ≡ I (mod N). By
// hand, 4 configurations × 3 trials over 3 shards: shard 0 owns 0, 3, 6, 9 (trial 0 of each
// configuration), shard 2 owns 2, 5, 8, 11: every number exactly once, 4 trials per shard.
TEST(Shard, EveryTrialBelongsToExactlyOneShardRoundRobin) {
  constexpr int kConfigs = 4, kTrials = 3, kShards = 3;
  std::vector<int> owners(kConfigs * kTrials, 0);
  for (int i = 0; i < kShards; ++i) {
    const Shard shard{i, kShards};
    int owned = 0;
    for (int n = 0; n < kConfigs * kTrials; ++n) {
      if (shard.owns(n)) {
        ++owners[n];
        ++owned;
      }
    }
    EXPECT_EQ(owned, 4) << "shard " << i;
  }
  for (int n = 0; n < kConfigs * kTrials; ++n) EXPECT_EQ(owners[n], 1) << n;
  EXPECT_TRUE((Shard{0, 3}.owns(9)));   // configuration 3, trial 0
  EXPECT_TRUE((Shard{2, 3}.owns(11)));  // configuration 3, trial 2
  EXPECT_TRUE(Shard{}.whole());
}

TEST(Sweep, ConfigurationsAreTheCartesianProductInAxisOrder) {
  const SweepSpec sweep = loadSweepText(kSweep, "small.json");
  const std::vector<SweepConfig> configs = configurations(sweep);
  ASSERT_EQ(configs.size(), 4u);
  EXPECT_EQ(configs[0].id, "p_detect-1.0_occlusion_model-canopy");
  EXPECT_EQ(configs[3].overrides,
            (std::vector<std::string>{"clock.duration=4.0", "sensing.p_detect=0.5",
                                      "sensing.occlusion_model=\"line_of_sight\""}));
}

TEST(Sweep, TheExampleSweepFileLoadsAsTwoTimesTwoConfigurations) {
  const SweepSpec sweep = loadSweep(CANOPY_SOURCE_DIR "/scenarios/sweeps/handover_horizons.json");
  EXPECT_EQ(sweep.trials, 10);
  const std::vector<SweepConfig> configs = configurations(sweep);
  ASSERT_EQ(configs.size(), 4u);
  EXPECT_EQ(configs[1].overrides,
            (std::vector<std::string>{"fusion.method=\"ci\"", "planner.algorithm=\"sma\"",
                                      "planner.horizon=5"}));
  for (const SweepConfig& config : configs) {  // every configuration is a valid scenario
    EXPECT_NO_THROW(spec::loadScenario(sweep.scenario, {config.overrides, std::nullopt, {}, 1.0}))
        << config.id;
  }
}

TEST(Sweep, ANamedAxisSetsItsGroupOfPathsForEachValue) {
  const SweepSpec sweep = loadSweepText(R"({
    "scenario": "demo",
    "axes": [{"name": "spread", "values": [2, 4],
              "set": [{"uavs.0.v_max": 2, "clock.duration": 3},
                      {"uavs.0.v_max": 4, "clock.duration": 5}]},
             {"path": "planner.horizon", "values": [1]}]})",
                                        "s.json");
  const std::vector<SweepConfig> configs = configurations(sweep);
  ASSERT_EQ(configs.size(), 2u);
  EXPECT_EQ(configs[1].id, "spread-4_horizon-1");
  EXPECT_EQ(configs[1].overrides,
            (std::vector<std::string>{"clock.duration=5", "uavs.0.v_max=4", "planner.horizon=1"}));
  EXPECT_EQ(configs[1].point, (std::vector<std::string>{"spread=4", "planner.horizon=1"}));
  const spec::ScenarioSpec spec =
      spec::loadScenario(sweep.scenario, {configs[1].overrides, std::nullopt, {}, 1.0});
  EXPECT_EQ(spec.duration, 5.0);
}

TEST(Sweep, ANamedAxisNeedsOneGroupPerValue) {
  try {
    loadSweepText(R"({"scenario": "demo", "axes": [{"name": "a", "values": [1, 2],
                      "set": [{"clock.duration": 3}]}]})",
                  "s.json");
    FAIL() << "expected a ScenarioError";
  } catch (const spec::ScenarioError& e) {
    EXPECT_EQ(e.field(), "axes[0].set");
    EXPECT_NE(std::string(e.what()).find("one object of overrides per value (2), got 1"),
              std::string::npos)
        << e.what();
  }
}

// A configuration that is not a valid scenario is blamed on the sweep's own field: the axis whose
// value made it (a path axis, a named axis's group) or the overrides every configuration gets.
TEST(Sweep, ABadConfigurationNamesTheSweepFilesAxis) {
  const auto blamed = [](const std::string& text) -> std::string {
    try {
      prepareSweep(loadSweepText(text, "bad_sweep.json"), fs::temp_directory_path() / "unused",
                   false, false);
    } catch (const spec::ScenarioError& e) {
      EXPECT_EQ(e.file(), "bad_sweep.json") << e.what();
      return e.field();
    }
    return "(loaded)";
  };
  EXPECT_EQ(blamed(R"({"scenario": "demo", "axes": [{"path": "planner.horizon", "values": [1]},
                      {"path": "uavs.0.v_max", "values": [2, -3]}]})"),
            "axes[1].path");
  EXPECT_EQ(blamed(R"({"scenario": "demo", "axes": [{"name": "fast", "values": [1, 2],
                      "set": [{"uavs.0.v_max": 3}, {"uavs.1.v_max": -1}]}]})"),
            "axes[0].set[1]");
  EXPECT_EQ(blamed(R"({"scenario": "demo", "set": {"tracking.sigma_a": -1},
                      "axes": [{"path": "planner.horizon", "values": [1]}]})"),
            "set");
}

TEST(Sweep, WithTrialsAndSeedChangesTheEffectiveTextToo) {
  const SweepSpec sweep = loadSweep(CANOPY_SOURCE_DIR "/scenarios/sweeps/handover_horizons.json");
  const SweepSpec fewer = withTrialsAndSeed(sweep, 3, 9);
  EXPECT_EQ(fewer.trials, 3);
  EXPECT_EQ(fewer.seed, 9u);
  const SweepSpec reloaded = loadSweepText(fewer.effective_json, "sweep.json");
  EXPECT_EQ(reloaded.trials, 3);
  EXPECT_EQ(reloaded.seed, 9u);
  EXPECT_EQ(reloaded.axes.size(), sweep.axes.size());
}

TEST(Sweep, TheSensitivityStudiesLoadWithEveryConfigurationValid) {
  for (const char* name : {"ra_distance_horizon", "je_occlusion_spacing"}) {
    const SweepSpec sweep =
        loadSweep(std::string(CANOPY_SOURCE_DIR "/scenarios/sweeps/") + name + ".json");
    ASSERT_GE(sweep.axes.size(), 2u) << name;
    for (const SweepConfig& config : configurations(sweep)) {
      EXPECT_NO_THROW(spec::loadScenario(sweep.scenario, {config.overrides, std::nullopt, {}, 1.0}))
          << config.id;
    }
  }
}

TEST(Sweep, TrialSeedsDependOnTheIndexOnly) {
  EXPECT_EQ(trialSeed(7, 2), trialSeed(7, 2));
  EXPECT_NE(trialSeed(7, 2), trialSeed(7, 3));
  EXPECT_NE(trialSeed(7, 2), trialSeed(8, 2));
}

TEST(Sweep, ResultsDoNotDependOnTheNumberOfThreads) {
  const SweepSpec sweep = loadSweepText(kSweep, "small.json");
  const fs::path one = freshDir("jobs1"), two = freshDir("jobs2");
  EXPECT_EQ(runSweep(sweep, {one, 1, {}, {}}), 12);
  EXPECT_EQ(runSweep(sweep, {two, 2, {}, {}}), 12);
  const auto a = trialFiles(one), b = trialFiles(two);
  EXPECT_EQ(a.size(), 12u);
  EXPECT_EQ(a, b);
}

// Ground robots are Box2D dynamic bodies stopped by trunks, walls and each other; their trials
// too are the same bits at 1 and 2 threads and over 3 shards run one after another.
TEST(Sweep, GroundRobotTrialsDoNotDependOnThreadsOrShards) {
  const SweepSpec sweep = loadSweepText(R"({
    "name": "robots", "scenario": "mixed_team", "trials": 2, "seed": 11,
    "set": {"clock.duration": 6.0},
    "axes": [{"path": "planner.occlusion_map", "values": ["dynamic", "none"]}]
  })",
                                        "robots.json");
  const fs::path one = freshDir("robots1"), two = freshDir("robots2"), shards = freshDir("robots3");
  EXPECT_EQ(runSweep(sweep, {one, 1, {}, {}}), 4);
  EXPECT_EQ(runSweep(sweep, {two, 2, {}, {}}), 4);
  for (int i = 0; i < 3; ++i) runSweep(sweep, {shards, 1, {}, Shard{i, 3}});
  const auto a = trialFiles(one);
  EXPECT_EQ(a.size(), 4u);
  EXPECT_EQ(a, trialFiles(two));
  EXPECT_EQ(a, trialFiles(shards));
}

TEST(Sweep, ResumingRunsOnlyTheMissingTrialsAndGivesTheSameResults) {
  const SweepSpec sweep = loadSweepText(kSweep, "small.json");
  const fs::path whole = freshDir("whole"), resumed = freshDir("resumed");
  runSweep(sweep, {whole, 2, {}, {}});
  runSweep(sweep, {resumed, 2, {}, {}});
  // Interrupt by hand: two finished trials vanish and a half-written temp file is left behind.
  const auto files = trialFiles(resumed);
  auto it = files.begin();
  fs::remove(resumed / it->first);
  std::ofstream(resumed / (it->first + ".tmp")) << "{\"scenario\": \"dem";
  fs::remove(resumed / (++it)->first);
  int last_resumed = -1;
  EXPECT_EQ(
      runSweep(sweep, {resumed, 2, [&](const SweepProgress& p) { last_resumed = p.resumed; }, {}}),
      2);
  EXPECT_EQ(last_resumed, 10);
  EXPECT_EQ(trialFiles(resumed), trialFiles(whole));
  EXPECT_EQ(runSweep(sweep, {resumed, 2, {}, {}}), 0);  // nothing left to do
}

// Shards run at once: a shard that starts while another writes a trial must not take that
// trial's temporary for a killed run's leftover (it once deleted it, and the writer failed).
// Shards leave temporaries alone; the whole run that finishes the sweep clears them.
TEST(Sweep, OnlyTheFinishingRunClearsTemporaries) {
  const SweepSpec sweep = loadSweepText(kSweep, "small.json");
  const fs::path dir = freshDir("temporaries");
  runSweep(sweep, {dir, 1, {}, Shard{0, 3}});
  const fs::path config = trialPath(dir, configurations(sweep)[0].id, 1).parent_path();
  const fs::path in_flight = config / "trial_0001.json.4242-0.tmp";  // as AtomicFile names them
  std::ofstream(in_flight) << "{\"scenario\": \"dem";
  runSweep(sweep, {dir, 1, {}, Shard{1, 3}});
  EXPECT_TRUE(fs::exists(in_flight)) << "a shard removed another run's temporary";
  runSweep(sweep, {dir, 1, {}, {}});
  EXPECT_FALSE(fs::exists(in_flight)) << "the finishing run left a temporary";
  EXPECT_EQ(trialFiles(dir).size(), 12u);
}

TEST(Sweep, RefusesADirectoryHoldingAnotherSweep) {
  const fs::path dir = freshDir("other");
  runSweep(loadSweepText(kSweep, "small.json"), {dir, 1, {}, {}});
  std::string changed = kSweep;
  changed.replace(changed.find("\"trials\": 3"), 11, "\"trials\": 4");
  EXPECT_THROW(runSweep(loadSweepText(changed, "small.json"), {dir, 1, {}, {}}),
               spec::ScenarioError);
}

TEST(Sweep, LoadsBackEveryTrialGroupedByConfiguration) {
  const fs::path dir = freshDir("load");
  runSweep(loadSweepText(kSweep, "small.json"), {dir, 2, {}, {}});
  const SweepResults results = loadSweepResults(dir);
  ASSERT_EQ(results.trials.size(), 4u);
  for (const auto& trials : results.trials) {
    ASSERT_EQ(trials.size(), 3u);
    EXPECT_EQ(trials[0].steps(), 21);  // 4 s of 0.2 s, plus the initial state
    EXPECT_EQ(trials[0].uavs, 2);
  }
  EXPECT_EQ(results.trials[0][1].seed, trialSeed(7, 1));
}

TEST(Sweep, RefusesToResumeWhenTheScenarioBehindItChanged) {
  const fs::path dir = freshDir("changed");
  fs::create_directories(dir);
  const fs::path scenario = dir / "walk.json";
  const std::string demo = readTextFile(spec::libraryDir() / "demo.json").value();
  std::ofstream(scenario) << demo;
  const std::string text = R"({"scenario": ")" + scenario.string() +
                           R"(", "trials": 1, "set": {"clock.duration": 1.0}})";
  const fs::path out = dir / "out";
  EXPECT_EQ(runSweep(loadSweepText(text, "s.json"), {out, 1, {}, {}}), 1);
  EXPECT_EQ(runSweep(loadSweepText(text, "s.json"), {out, 1, {}, {}}),
            0);  // resumes: nothing to do
  // The same sweep text, but the scenario file now says something else.
  std::string changed = demo;
  changed.insert(changed.find("\"description\": \"") + 16, "changed: ");
  std::ofstream(scenario) << changed;
  try {
    runSweep(loadSweepText(text, "s.json"), {out, 1, {}, {}});
    FAIL() << "expected a ScenarioError";
  } catch (const spec::ScenarioError& e) {
    EXPECT_NE(std::string(e.what()).find("scenarios.json"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("changed since its trials ran"), std::string::npos);
  }
}

TEST(Sweep, BadSweepFilesNameTheFieldAndBadOverridesFailBeforeAnyTrial) {
  EXPECT_THROW(loadSweepText(R"({"scenario": "no_such_scenario"})", "s.json"), spec::ScenarioError);
  EXPECT_THROW(loadSweepText(R"({"scenario": "demo", "trials": 0})", "s.json"),
               spec::ScenarioError);
  EXPECT_THROW(loadSweepText(R"({"scenario": "demo", "axes": [{"path": "x"}]})", "s.json"),
               spec::ScenarioError);
  const fs::path dir = freshDir("bad");
  const SweepSpec bad = loadSweepText(
      R"({"scenario": "demo", "axes": [{"path": "planner.horizon", "values": [0]}]})", "s.json");
  try {
    runSweep(bad, {dir, 1, {}, {}});
    FAIL() << "expected a ScenarioError";
  } catch (const spec::ScenarioError& e) {
    EXPECT_EQ(e.file(), "s.json");  // the sweep's own field, and the scenario's in the message
    EXPECT_EQ(e.field(), "axes[0].path");
    EXPECT_NE(std::string(e.what()).find("planner.horizon"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(dir / "trials"));
  EXPECT_FALSE(fs::exists(dir / "sweep.json"));  // nothing is written before every config loads
}

}  // namespace
}  // namespace canopy::experiments
