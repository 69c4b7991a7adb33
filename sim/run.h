#pragma once
// `canopy run`: a scenario to manifest.json, record.jsonl and summary.json in one directory.
#include <filesystem>
#include <string>
#include <vector>

#include "sim/compact_record.h"
#include "sim/record_lines.h"
#include "sim/step_observer.h"
#include "spec/scenario_spec.h"

namespace canopy::sim {

struct RunOptions {
  std::filesystem::path out_dir;         // created if missing
  std::string command_line;              // recorded in the manifest
  std::vector<StepObserver*> observers;  // after the record and summary, e.g. the frames
  int threads = 1;  // Simulation's threads (1..Simulation::kMaxThreads): the same bits at any count
  /// record.jsonl, record.jsonl.zst, or by the estimated size (record_lines.h)
  RecordFormat record = RecordFormat::automatic;
  BlockSize record_blocks{};  // the compact form's blocks
};

struct RunResult {
  int steps = 0;
  double wall_seconds = 0.0;
  std::string summary_json;
};

/// Runs the scenario to its end and writes the outputs: manifest.json, then record.jsonl (or
/// record.jsonl.zst, options.record) and
/// timings.jsonl (streamed, published when the run ends), then summary.json. An earlier run's
/// files in out_dir are removed first; a run that fails (WriteError on any write, or an exception
/// from an observer, a state that is not finite) removes whatever of these it wrote, frames
/// included, so out_dir never holds a partial record or
/// a summary of a run that did not finish. checkRunOutputs runs before anything is removed.
RunResult runScenario(const spec::ScenarioSpec& spec, const RunOptions& options);

/// Refuses (OutputRefused) a run folder where a file of the run (manifest.json, record.jsonl[.zst],
/// timings.jsonl, summary.json, replay.html, frames.mp4, frames/*) exists and is not a regular
/// file or a link: a device, FIFO, socket or directory there is not the run's to replace.
/// runScenario calls it first; the command line calls it before anything else is built.
void checkRunOutputs(const std::filesystem::path& out_dir);

/// manifest.json's content: version, scenario, hash of the effective config, seed, config.
std::string manifestJson(const spec::ScenarioSpec& spec, const std::string& command_line);

}  // namespace canopy::sim
