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
/// A result file read back: the first byte picks the reader (mod 5: a run's manifest.json, a
/// record.jsonl against the demo's scenario, a trial file, a golden coverage CSV against a
/// fixed one, a sweep folder's sweep.json), the rest is the file's bytes (written to the
/// sandbox for the readers that take a path).
bool readResultInput(std::string_view data);
/// A record.jsonl read back by the truth reader (sim::readRecordTruth) against the demo's
/// scenario: the bytes are the file. The same lines written compact (record.jsonl.zst, small
/// blocks) must be read alike (the same number of steps, or refused too), and the bytes read as
/// a compact record are refused or read, never a crash.
bool readRecordInput(std::string_view data);
/// A run folder read back by the replay's reader (replay::readRunFolder): the demo's manifest,
/// the bytes up to the first NUL as record.jsonl, and after it summary.json (without a NUL, a
/// summary with one OSPA value per non-blank line for each of the demo's UAVs, so that a good
/// record is read to the end).
bool readReplayInput(std::string_view data);
/// Python's edit of a scenario (Scenario.__setitem__): the first line is a dotted path, the
/// rest a JSON value; it is set into the demo's effective configuration as Python sets it (a
/// missing key of an object is added, a list index must exist), and the edited configuration,
/// dumped as json.dumps does, is loaded with loadScenarioText — the C++ path of every edit.
bool pythonEditInput(std::string_view data);

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
