#pragma once
// Monte Carlo sweeps: a base scenario, axes of --set values, and a number of trials per
// configuration. Trials run on a thread pool, each result is written atomically, and a sweep
// killed at any moment resumes without losing or redoing a finished trial. Results do not
// depend on the number of threads.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "experiments/trial.h"
#include "spec/loader.h"

namespace canopy::experiments {

/// An axis varies one --set path over its values, or, when it is named, sets for each of its
/// values a group of paths at once (a layout parameter that moves several things together):
///   {"path": "planner.horizon", "values": [1, 5]}
///   {"name": "gap", "values": [10, 14], "set": [{"targets.2.path.start.1": -10}, {…: -14}]}
struct SweepAxis {
  std::string path;                 // the --set path, or the axis name when `set` is not empty
  std::vector<std::string> values;  // each a JSON value as text
  std::vector<std::vector<std::string>> set;  // per value, its "path=value" overrides (named)
};

struct SweepSpec {
  std::string file;  // the sweep file (errors of its axes name it); not part of its identity
  std::string name;
  std::string scenario;  // base scenario: a path (resolved beside the sweep file) or a library name
  int trials = 1;        // per configuration
  std::uint64_t seed = 1;          // trial i of every configuration gets trialSeed(seed, i)
  std::vector<std::string> fixed;  // "path=value" overrides applied to every configuration
  std::vector<SweepAxis> axes;     // the Cartesian product of their values
  std::string effective_json;      // the sweep as read, for DIR/sweep.json
  /// How each configuration's scenario is loaded (allowed folders, work budget): a choice of the
  /// command line, not part of the sweep's identity or of DIR/sweep.json.
  spec::LoadOptions load;
};

/// One point of the Cartesian product.
struct SweepConfig {
  /// A directory name, e.g. "algorithm-sma_horizon-5": each axis's last path component and its
  /// value, characters unsafe in a file name as '_'. Where two points would get the same name
  /// (values "a b" and "a_b"), each of them gets "~" and a hash of its exact point as well, so
  /// ids are unique whatever the values.
  std::string id;
  std::vector<std::string> overrides;  // fixed, then this point's axis values
  std::vector<std::string> point;      // per axis "path-or-name=value", in axis order
};

/// A path for `sweep`: an existing file, else NAME or NAME.json in the built-in sweeps
/// (spec::builtinScenarioDir() / "sweeps"), so that `canopy sweep handover_horizons` runs by name
/// as scenarios do; a ScenarioError naming the built-in sweeps when neither exists.
std::filesystem::path resolveSweep(const std::string& sweep);
/// The names of the built-in sweeps, sorted.
std::vector<std::string> builtinSweeps();
/// Reads and validates a sweep file (ScenarioError: file, field, expectation): axes unique, no
/// value twice on an axis, and the number of configurations and trials within the work budget
/// (spec/budget.h, scaled by load.budget_scale) before any configuration is built.
SweepSpec loadSweep(const std::string& path, const spec::LoadOptions& load = {});
SweepSpec loadSweepText(const std::string& text, const std::string& file,
                        const spec::LoadOptions& load = {});

/// The same sweep with another number of trials per configuration and another seed (its
/// effective text says so too, so that DIR/sweep.json matches what runs).
SweepSpec withTrialsAndSeed(SweepSpec sweep, int trials, std::uint64_t seed);

std::vector<SweepConfig> configurations(const SweepSpec& sweep);
/// The seed of trial `index` (the same in every configuration: common random numbers).
std::uint64_t trialSeed(std::uint64_t sweep_seed, int index);

struct SweepProgress {
  int done = 0;  // finished trials, including those found on disk
  int total = 0;
  int resumed = 0;  // found on disk at start
};

/// A fixed partition of a sweep's trials over several runs (`canopy sweep --shard I/N`, a Slurm
/// job array): the trials are numbered configuration-major, trial t of configuration c being
/// c·trials + t, and shard I of N (0 ≤ I < N) owns the numbers equal to I modulo N. Interleaved,
/// so that every configuration's trials, the expensive ones too, spread evenly over the shards.
struct Shard {
  int index = 0;
  int count = 1;
  bool owns(int trial_number) const { return trial_number % count == index; }
  bool whole() const { return count == 1; }
};

struct SweepOptions {
  std::filesystem::path out_dir;
  int jobs = 1;
  std::function<void(const SweepProgress&)> on_progress;  // called from worker threads, serialised
  Shard shard;                                            // the trials this run owns (default: all)
};

/// The fingerprint of a configuration's effective scenario that DIR/scenarios.json keeps: 16 hex
/// digits of the FNV-1a of its effective configuration.
std::string scenarioFingerprint(const spec::ScenarioSpec& spec);

/// A sweep checked against its directory and ready to run.
struct PreparedSweep {
  std::vector<SweepConfig> configs;
  std::vector<spec::ScenarioSpec> specs;  // per configuration, validated
  std::vector<int> todo;                  // trial numbers not finished yet, in increasing order
  int total = 0;                          // configurations × trials
};

/// Loads (and so validates) every configuration, then checks the directory: resuming into one
/// whose DIR/sweep.json or DIR/scenarios.json (an FNV-1a fingerprint of each configuration's
/// effective scenario) differs throws, unless it holds no finished trial yet (then the new sweep
/// replaces the old) and `strict` is off — shards run strict, so that shards of two different
/// sweeps never mix in one directory. With `write`, writes both files (atomically, identical
/// bytes from every run of the same sweep) and, unless `strict`, clears temporaries a killed run
/// left (a shard must not: a shard running at the same time may be writing one). Lists the
/// trials with no regular file yet.
PreparedSweep prepareSweep(const SweepSpec& sweep, const std::filesystem::path& out_dir,
                           bool strict = false, bool write = true);

/// Hands out the next entry of a todo list to run, thread-safe; nullopt when none is left.
using NextTrial = std::function<std::optional<std::size_t>()>;

/// Runs todo entries of a prepared sweep on `jobs` threads, each pulling from `next` until it
/// returns nullopt, writing each trial atomically; returns the number run. The first failure
/// stops the handing out and is rethrown. progress.total is `expected` (finished + to run here).
int runTrials(const SweepSpec& sweep, const PreparedSweep& prepared,
              const std::filesystem::path& out_dir, int jobs, const NextTrial& next,
              SweepProgress progress,
              const std::function<void(const SweepProgress&)>& on_progress = {});

/// Writes DIR/summary.json from every finished trial (summariseSweep).
void finishSweep(const std::filesystem::path& out_dir);

/// Runs every missing trial the shard owns; when the shard is the whole sweep, then writes
/// DIR/summary.json. Returns the number of trials it ran.
int runSweep(const SweepSpec& sweep, const SweepOptions& options);

/// How far a sweep directory is: per configuration (sweep order) its finished trials.
struct SweepStatus {
  std::string name;
  int trials_per_config = 0;
  std::vector<std::pair<std::string, int>> finished;  // configuration id, finished trials
};
SweepStatus sweepStatus(const std::filesystem::path& out_dir);

/// Where trial `index` of configuration `config_id` lives under a sweep directory.
std::filesystem::path trialPath(const std::filesystem::path& out_dir, const std::string& config_id,
                                int index);

/// Every finished trial under a sweep directory, grouped by configuration in sweep order.
struct SweepResults {
  SweepSpec sweep;
  std::vector<SweepConfig> configs;
  std::vector<std::vector<TrialResult>> trials;  // [config][trial]
};
SweepResults loadSweepResults(const std::filesystem::path& out_dir,
                              const spec::LoadOptions& load = {});

/// summary.json of a sweep directory: per configuration its overrides, the trials finished, and
/// means over trials and steps of OSPA (m), Σ tr(P_pos) (m²) and the fraction of targets visible
/// to some UAV. Depends only on the finished trials, never on how they were run or resumed.
std::string summariseSweep(const SweepResults& results);

}  // namespace canopy::experiments
