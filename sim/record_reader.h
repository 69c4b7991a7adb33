#pragma once
// A finished run read back from its folder: the scenario it ran (manifest.json's effective
// configuration) and, per recorded step, the truth (record.jsonl's "k", "t", the UAVs' poses and
// the targets' positions). The reader beside the writer (recorder.h): `canopy coverage`, the
// Python readers and the analysis read runs through it. Files are read as result files are: a
// regular file, never through a link or from a FIFO, nested at most kMaxJsonDepth deep; every
// error is a ScenarioError naming the file, the line and the field.
#include <filesystem>
#include <string>
#include <vector>

#include "sim/record_lines.h"
#include "spec/scenario_spec.h"
#include "world/snapshot.h"

namespace canopy::sim {

/// The scenario of the run whose manifest.json is `path` (its "effective_config", with every
/// default filled in, loaded as a scenario file would be).
spec::ScenarioSpec readManifest(const std::filesystem::path& path);

/// The truth of every line of the record at `path` (record.jsonl or record.jsonl.zst) within
/// `range`, each line read whole by the one line reader (record_step_reader.h) against `spec`.
/// WorldSnapshot's step, time, the UAVs' position, velocity, yaw, contacts and altitude (a UAV
/// without one: its scenario's) and the targets' position and velocity are filled.
std::vector<world::WorldSnapshot> readRecordTruth(const std::filesystem::path& path,
                                                  const spec::ScenarioSpec& spec,
                                                  const LineRange& range = {});

struct RunRecord {
  spec::ScenarioSpec spec;
  std::vector<world::WorldSnapshot> truth;  // one per recorded step, in order
};

/// manifest.json and the record (either form, recordFileOf) of the run folder `run_dir` (the
/// --out of `canopy run`), the steps of `range` only.
RunRecord readRun(const std::filesystem::path& run_dir, const LineRange& range = {});

}  // namespace canopy::sim
