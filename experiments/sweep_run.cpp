// Running a sweep's trials: checking the directory, handing out the trials to threads (and, for
// shards or MPI, to several processes), and the summary once every trial is there.
#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>

#include "core/text_file.h"
#include "experiments/sweep.h"
#include "spec/budget.h"
#include "spec/error.h"
#include "spec/json_reader.h"

namespace canopy::experiments {
namespace fs = std::filesystem;
using spec::Json;

namespace {

bool finished(const fs::path& trial_file) {
  // Only a regular file counts as finished: a link or FIFO planted there is run again (and
  // replaced, since the trial's file is renamed over it).
  std::error_code error;
  return fs::symlink_status(trial_file, error).type() == fs::file_type::regular;
}

// A run killed mid-write leaves its temporary behind (never trusted): clear them.
void clearTemporaries(const fs::path& config_dir) {
  std::error_code list_error;
  for (auto it = fs::directory_iterator(config_dir, list_error);
       !list_error && it != fs::directory_iterator(); it.increment(list_error)) {
    const std::string name = it->path().filename().string();
    if (name.rfind("trial_", 0) == 0 && name.size() > 4 && name.ends_with(".tmp")) {
      std::error_code ignored;
      fs::remove(it->path(), ignored);
    }
  }
}

// The field of the sweep file that made configuration `config` fail to load with `error`: the
// axis whose override the error names ("axes[i].path", or "axes[i].set[v]" for a named axis),
// else "set" for the overrides every configuration gets, else "axes".
std::string axisOf(const SweepSpec& sweep, const SweepConfig& config,
                   const spec::ScenarioError& error) {
  // "uavs[0].v_max" → "uavs.0.v_max", the --set spelling of the paths in the sweep.
  std::string dotted;
  for (const char c : error.field()) {
    if (c == '[')
      dotted += '.';
    else if (c != ']')
      dotted += c;
  }
  const auto names = [&dotted](const std::string& assignment) {
    const std::string path = assignment.substr(0, assignment.find('='));
    return !path.empty() && (dotted == path || dotted.starts_with(path + "."));
  };
  for (std::size_t a = 0; a < sweep.axes.size(); ++a) {
    const SweepAxis& axis = sweep.axes[a];
    const std::string at = "axes[" + std::to_string(a) + "]";
    if (axis.set.empty()) {
      if (names(axis.path)) return at + ".path";
      continue;
    }
    for (std::size_t v = 0; v < axis.set.size(); ++v) {
      if (config.point.size() > a && config.point[a] != axis.path + "=" + axis.values[v]) continue;
      for (const std::string& assignment : axis.set[v])
        if (names(assignment)) return at + ".set[" + std::to_string(v) + "]";
    }
  }
  for (const std::string& assignment : sweep.fixed)
    if (names(assignment)) return "set";
  return "axes";
}

}  // namespace

PreparedSweep prepareSweep(const SweepSpec& sweep, const fs::path& out_dir, bool strict,
                           bool write) {
  PreparedSweep prepared;
  prepared.configs = configurations(sweep);
  double trees = 0.0;                                   // held in memory for the whole sweep
  for (const SweepConfig& config : prepared.configs) {  // bad overrides fail before any write
    spec::LoadOptions load = sweep.load;
    load.overrides = config.overrides;
    try {
      prepared.specs.push_back(spec::loadScenario(sweep.scenario, load));
    } catch (const spec::ScenarioError& e) {
      throw spec::ScenarioError(
          sweep.file.empty() ? sweep.name : sweep.file, axisOf(sweep, config, e),
          "configuration " + config.id + " is not a valid scenario: " + e.what());
    }
    trees += static_cast<double>(prepared.specs.back().trees.size());
  }
  if (const double limit = spec::workLimits(sweep.load.budget_scale).trees; trees > limit) {
    throw spec::ScenarioError(
        sweep.name, "axes",
        spec::budgetMessage(trees, limit, "trees over all configurations together"));
  }

  // A directory with no finished trial holds nothing to protect: a corrected sweep replaces it
  // (but a shard never replaces another sweep's files: shards of two sweeps would mix).
  std::error_code error;
  const bool has_trials =
      fs::exists(out_dir / "trials", error) && !fs::is_empty(out_dir / "trials", error);
  const bool guarded = has_trials || strict;
  const fs::path manifest = out_dir / "sweep.json";
  // Read back bounded like every result file: a FIFO, link or directory in their place is named.
  const auto present = [](const fs::path& path) {
    std::error_code ignored;
    return fs::exists(fs::symlink_status(path, ignored));
  };
  if (has_trials && !present(manifest)) {
    throw spec::ScenarioError(
        out_dir.string(), "",
        "this directory holds trials but no sweep.json: they belong to another sweep (or to "
        "none); choose another --out");
  }
  if (guarded && present(manifest) &&
      spec::readResultText(manifest, "the sweep.json that `canopy sweep` writes") !=
          sweep.effective_json + "\n") {
    throw spec::ScenarioError(
        manifest.string(), "",
        "this directory belongs to another sweep (its sweep.json differs from this "
        "sweep's); choose another --out");
  }
  // The same sweep text over a changed scenario file (or changed defaults) would resume on
  // trials of another scenario: each configuration's effective scenario is fingerprinted.
  Json fingerprints = Json::object();
  for (std::size_t c = 0; c < prepared.configs.size(); ++c)
    fingerprints[prepared.configs[c].id] = scenarioFingerprint(prepared.specs[c]);
  const fs::path scenarios_file = out_dir / "scenarios.json";
  const std::string fingerprint_text = fingerprints.dump(2) + "\n";
  if (guarded && present(scenarios_file) &&
      spec::readResultText(scenarios_file, "the scenarios.json that `canopy sweep` writes") !=
          fingerprint_text) {
    throw spec::ScenarioError(
        scenarios_file.string(), "",
        "the scenario behind this sweep has changed since its trials ran (a "
        "configuration's effective scenario differs); choose another --out or "
        "remove the directory");
  }
  if (write) {
    fs::create_directories(out_dir);
    writeFileAtomically(manifest, sweep.effective_json + "\n");
    writeFileAtomically(scenarios_file, fingerprint_text);
  }

  const int per_config = sweep.trials;
  prepared.total = static_cast<int>(prepared.configs.size()) * per_config;
  for (int c = 0; c < static_cast<int>(prepared.configs.size()); ++c) {
    // Not in a strict (shard or MPI) run: shards run at once, and another shard's temporary is
    // in flight, not left over. The whole run that finishes the sweep clears them.
    if (write && !strict)
      clearTemporaries(trialPath(out_dir, prepared.configs[c].id, 0).parent_path());
    for (int t = 0; t < per_config; ++t) {
      if (!finished(trialPath(out_dir, prepared.configs[c].id, t)))
        prepared.todo.push_back(c * per_config + t);
    }
  }
  return prepared;
}

int runTrials(const SweepSpec& sweep, const PreparedSweep& prepared, const fs::path& out_dir,
              int jobs, const NextTrial& next, SweepProgress progress,
              const std::function<void(const SweepProgress&)>& on_progress) {
  std::mutex progress_mutex;
  std::exception_ptr failure;
  std::atomic<bool> stop{false};
  std::atomic<int> ran{0};
  if (on_progress) on_progress(progress);
  auto worker = [&] {
    while (!stop) {
      const std::optional<std::size_t> j = next();
      if (!j) return;
      const int number = prepared.todo.at(*j);
      const int config = number / sweep.trials, index = number % sweep.trials;
      try {
        spec::ScenarioSpec spec = prepared.specs[config];
        spec.seed = trialSeed(sweep.seed, index);
        const TrialResult trial = runTrial(spec, prepared.configs[config].id);
        writeFileAtomically(trialPath(out_dir, trial.config_id, index), trialToJson(trial) + "\n");
      } catch (...) {
        const std::lock_guard lock(progress_mutex);
        if (!failure) failure = std::current_exception();
        stop = true;  // stop taking work
        return;
      }
      ++ran;
      const std::lock_guard lock(progress_mutex);
      ++progress.done;
      if (on_progress) on_progress(progress);
    }
  };
  std::vector<std::jthread> pool;
  for (int w = 0; w < std::max(1, jobs); ++w) pool.emplace_back(worker);
  pool.clear();  // joins
  if (failure) std::rethrow_exception(failure);
  return ran;
}

void finishSweep(const fs::path& out_dir) {
  writeFileAtomically(out_dir / "summary.json", summariseSweep(loadSweepResults(out_dir)));
}

int runSweep(const SweepSpec& sweep, const SweepOptions& options) {
  if (options.shard.count < 1 || options.shard.index < 0 ||
      options.shard.index >= options.shard.count) {
    throw spec::ScenarioError("--shard", "", "expected I/N with 0 <= I < N");
  }
  const PreparedSweep prepared = prepareSweep(sweep, options.out_dir, !options.shard.whole(), true);
  std::vector<std::size_t> mine;  // indices into todo that this shard owns
  for (std::size_t j = 0; j < prepared.todo.size(); ++j) {
    if (options.shard.owns(prepared.todo[j])) mine.push_back(j);
  }
  int owned = 0;
  for (int number = 0; number < prepared.total; ++number) owned += options.shard.owns(number);
  SweepProgress progress;
  progress.total = owned;
  progress.resumed = owned - static_cast<int>(mine.size());
  progress.done = progress.resumed;
  std::atomic<std::size_t> next{0};
  const NextTrial local = [&]() -> std::optional<std::size_t> {
    const std::size_t k = next++;
    if (k >= mine.size()) return std::nullopt;
    return mine[k];
  };
  const int jobs = std::min(options.jobs, static_cast<int>(std::max<std::size_t>(1, mine.size())));
  const int ran =
      runTrials(sweep, prepared, options.out_dir, jobs, local, progress, options.on_progress);
  if (options.shard.whole()) finishSweep(options.out_dir);
  return ran;
}

SweepStatus sweepStatus(const fs::path& out_dir) {
  const fs::path manifest = out_dir / "sweep.json";
  std::error_code error;
  if (!fs::exists(fs::symlink_status(manifest, error))) {
    throw spec::ScenarioError(out_dir.string(), "", "not a sweep directory (no sweep.json)");
  }
  const SweepSpec sweep =
      loadSweepText(spec::readResultText(manifest, "the sweep.json that `canopy sweep` writes"),
                    manifest.string(), spec::LoadOptions{});
  SweepStatus status;
  status.name = sweep.name;
  status.trials_per_config = sweep.trials;
  for (const SweepConfig& config : configurations(sweep)) {
    int done = 0;
    for (int t = 0; t < sweep.trials; ++t) done += finished(trialPath(out_dir, config.id, t));
    status.finished.emplace_back(config.id, done);
  }
  return status;
}

}  // namespace canopy::experiments
