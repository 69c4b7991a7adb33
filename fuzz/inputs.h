#pragma once
// The entry points of the fuzz targets, shared with their regression test
// (tests/spec/fuzz_regression_test.cpp): each feeds raw bytes to one loader and returns true
// when they load, false on a ScenarioError. Those two are the contract; anything else escapes:
// another exception, or a crash, leak, UB or hang that the sanitizers and libFuzzer catch.
#include <filesystem>
#include <string_view>
#include <vector>

namespace canopy::fuzz {

/// Scenario text, then after the first NUL byte the --set overrides, one per line (empty lines
/// skipped): loadScenarioText with LoadOptions::overrides.
bool loadScenarioInput(std::string_view data);
/// Sweep text: loadSweepText, then configurations (no trials run).
bool loadSweepInput(std::string_view data);
/// Track CSV text: parseTrackCsv.
bool parseTrackInput(std::string_view data);

struct Target {
  const char* name;  // the fuzz target (fuzz/<name>.cpp) and its folders of inputs
  bool (*run)(std::string_view data);
};
/// Every target, in a fixed order.
const std::vector<Target>& targets();

/// The temporary folder the inputs are named in (created once per process, removed at exit). It
/// holds only `track.csv` and `layouts/grove.json`, so that includes and track files in the
/// inputs can resolve, and to nothing else but the scenario library.
const std::filesystem::path& sandboxDir();

}  // namespace canopy::fuzz
