#pragma once
// A finished run read back from its folder: the scenario it ran (manifest.json's effective
// configuration) and, per recorded step, the truth (record.jsonl's "k", "t", the UAVs' poses and
// the targets' positions). The reader beside the writer (recorder.h): `canopy coverage`, the
// Python readers and the analysis read runs through it. Files are read as result files are: a
// regular file, never through a link or from a FIFO, nested at most kMaxJsonDepth deep; every
// error is a ScenarioError naming the file, the line and the field.
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "spec/scenario_spec.h"
#include "world/snapshot.h"

namespace canopy::sim {

/// The scenario of the run whose manifest.json is `path` (its "effective_config", with every
/// default filled in, loaded as a scenario file would be).
spec::ScenarioSpec readManifest(const std::filesystem::path& path);

/// Calls line_fn(line, number) for each line of a record's text that is not blank, numbered from
/// 1, without its '\n'. The text is held once by the caller; one line at a time is copied out.
template <class LineFn>
void forEachRecordLine(const std::string& text, LineFn&& line_fn) {
  std::size_t next = 0;
  for (int number = 1; next < text.size(); ++number) {
    const std::size_t end = std::min(text.find('\n', next), text.size());
    const std::string line = text.substr(next, end - next);
    next = end + 1;
    if (line.find_first_not_of(" \t\r") != std::string::npos) line_fn(line, number);
  }
}

/// The truth of every line of the record.jsonl at `path`, checked against `spec`: one entry per
/// UAV and per target on every line. WorldSnapshot's step, time, uavs[].position and yaw and
/// targets[].position are filled; nothing else is recorded as truth.
std::vector<world::WorldSnapshot> readRecordTruth(const std::filesystem::path& path,
                                                  const spec::ScenarioSpec& spec);

struct RunRecord {
  spec::ScenarioSpec spec;
  std::vector<world::WorldSnapshot> truth;  // one per recorded step, in order
};

/// manifest.json and record.jsonl of the run folder `run_dir` (the --out of `canopy run`).
RunRecord readRun(const std::filesystem::path& run_dir);

}  // namespace canopy::sim
