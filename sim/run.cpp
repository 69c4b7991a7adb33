#include "sim/run.h"

#include <array>
#include <chrono>
#include <cstdio>
#include <optional>
#include <nlohmann/json.hpp>

#include "core/output_file.h"
#include "core/random.h"
#include "core/text_file.h"
#include "core/version.h"
#include "sim/observer_thread.h"
#include "sim/recorder.h"
#include "sim/simulation.h"
#include "sim/summary.h"

namespace canopy::sim {

std::string manifestJson(const spec::ScenarioSpec& spec, const std::string& command_line) {
  using Json = nlohmann::json;
  char hash[17];
  std::snprintf(hash, sizeof hash, "%016llx",
                static_cast<unsigned long long>(fnv1a64(spec.effective_config)));
  Json manifest;
  manifest["canopy_version"] = kVersion;
  manifest["git_commit"] = kGitCommit;
  manifest["scenario"] = spec.name;
  manifest["scenario_file"] = spec.file.string();
  manifest["config_hash_fnv1a64"] = hash;
  manifest["seed"] = spec.seed;
  manifest["command"] = command_line;
  manifest["labels"] = spec.labels;
  manifest["trees"] = spec.trees.size();
  // The effective configuration is already dump(2)'s text: it is spliced in one level deeper
  // rather than parsed again (9·10⁶ instructions for a 70 kB scenario). The key first holds a
  // marker string; inside any dumped string every quote is escaped, so the line "key": "marker"
  // occurs once, where the key is.
  constexpr const char* kSpliceMark = "spliced: the effective configuration";
  manifest["effective_config"] = kSpliceMark;
  // The command line and the file's path are the user's bytes, not necessarily UTF-8: invalid
  // bytes are recorded as U+FFFD instead of failing the run.
  std::string text = manifest.dump(2, ' ', false, Json::error_handler_t::replace);
  const std::string marked = std::string("\n  \"effective_config\": \"") + kSpliceMark + "\"";
  std::string nested = "\n  \"effective_config\": ";
  for (const char c : spec.effective_config) {
    nested += c;
    if (c == '\n') nested += "  ";  // dump(2) indents each level by two spaces
  }
  text.replace(text.find(marked), marked.size(), nested);
  return text;
}

namespace {

// What a run writes in its directory. summary.json, the mark of a finished run, comes first: it
// is removed before anything else and written after everything else.
constexpr std::array<const char*, 5> kRunFiles = {"summary.json", "manifest.json", kRecordJsonlName,
                                                  kRecordCompactName, "timings.jsonl"};

RunResult simulate(const spec::ScenarioSpec& spec, const RunOptions& options) {
  writeFileAtomically(options.out_dir / "manifest.json",
                      manifestJson(spec, options.command_line) + "\n");
  const auto start = std::chrono::steady_clock::now();
  Simulation sim(spec, options.threads);
  Recorder recorder(options.out_dir, spec, options.record, options.record_blocks);
  SummaryBuilder summary(spec);
  std::vector<StepObserver*> observers = {&recorder, &summary};
  // With threads to spare, the record and summary are written one step behind, on their own
  // thread (the caller's observers, frames among them, stay on this one).
  std::optional<ObserverThread> behind;
  if (options.threads > 1) {
    behind.emplace(observers);
    observers = {&*behind};
  }
  observers.insert(observers.end(), options.observers.begin(), options.observers.end());
  runToEnd(sim, observers);
  if (behind) behind->finish();
  recorder.commit();
  RunResult result;
  result.steps = summary.steps();
  result.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.summary_json = summary.json(result.wall_seconds);
  writeFileAtomically(options.out_dir / "summary.json", result.summary_json + "\n");
  return result;
}

// Frames of an earlier run in the same folder (frames/frame_NNNNNN.png) would be taken for this
// run's: they go before it starts. A run with --frames writes its own after this; the folder
// itself stays (its writer may have made it already), and a link in its place is not followed.
void removeStaleFrames(const std::filesystem::path& out_dir) {
  const std::filesystem::path frames = out_dir / "frames";
  std::error_code error;
  if (!std::filesystem::is_directory(std::filesystem::symlink_status(frames, error))) return;
  for (const auto& entry : std::filesystem::directory_iterator(frames, error)) {
    const std::string name = entry.path().filename().string();
    if (name.starts_with("frame_") && entry.path().extension() == ".png")
      removeOutputFile(entry.path());
  }
}

}  // namespace

void checkRunOutputs(const std::filesystem::path& out_dir) {
  for (const char* name : kRunFiles) checkOutputFile(out_dir / name);
  for (const char* name : {"replay.html", "frames.mp4"}) checkOutputFile(out_dir / name);
  checkOutputEntries(out_dir / "frames");
}

RunResult runScenario(const spec::ScenarioSpec& spec, const RunOptions& options) {
  checkRunOutputs(options.out_dir);
  makeOutputDirectories(options.out_dir, options.out_dir);
  // The files of an earlier run would be read as this run's if this one failed part way.
  for (const char* name : kRunFiles) removeOutputFile(options.out_dir / name);
  removeStaleFrames(options.out_dir);  // (a frame writer writes its first frame at the first step)
  try {
    return simulate(spec, options);
  } catch (...) {
    // A failed run leaves none of its files: nothing a later reader could take for a result.
    for (const char* name : kRunFiles) {
      std::error_code ignored;
      std::filesystem::remove(options.out_dir / name, ignored);
    }
    try {
      removeStaleFrames(options.out_dir);  // the frames of the steps before it, too
    } catch (const std::exception&) {
      // the run's own error is the one to report
    }
    throw;
  }
}

}  // namespace canopy::sim
