#pragma once
// Monte Carlo sweeps: a base scenario, axes of --set values, and a number of trials per
// configuration. Trials run on a thread pool, each result is written atomically, and a sweep
// killed at any moment resumes without losing or redoing a finished trial. Results do not
// depend on the number of threads.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "scenarios/loader.h"
#include "scenarios/trial.h"

namespace canopy::scenarios {

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
  std::string name;
  std::string scenario;  // base scenario: a path (resolved beside the sweep file) or a library name
  int trials = 1;        // per configuration
  std::uint64_t seed = 1;          // trial i of every configuration gets trialSeed(seed, i)
  std::vector<std::string> fixed;  // "path=value" overrides applied to every configuration
  std::vector<SweepAxis> axes;     // the Cartesian product of their values
  std::string effective_json;      // the sweep as read, for DIR/sweep.json
  /// How each configuration's scenario is loaded (allowed folders, work budget): a choice of the
  /// command line, not part of the sweep's identity or of DIR/sweep.json.
  LoadOptions load;
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

/// Reads and validates a sweep file (ScenarioError: file, field, expectation): axes unique, no
/// value twice on an axis, and the number of configurations and trials within the work budget
/// (scenarios/budget.h, scaled by load.budget_scale) before any configuration is built.
SweepSpec loadSweep(const std::string& path, const LoadOptions& load = {});
SweepSpec loadSweepText(const std::string& text, const std::string& file,
                        const LoadOptions& load = {});

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

struct SweepOptions {
  std::filesystem::path out_dir;
  int jobs = 1;
  std::function<void(const SweepProgress&)> on_progress;  // called from worker threads, serialised
};

/// Runs every missing trial, then writes DIR/summary.json (summariseSweep); returns the number of
/// trials it ran. Every configuration is loaded (and so validated) before anything is written.
/// DIR/sweep.json holds the sweep and DIR/scenarios.json a fingerprint (FNV-1a of the effective
/// scenario) per configuration; resuming into a directory where either differs throws, unless
/// the directory holds no finished trial yet (then the new sweep replaces the old).
int runSweep(const SweepSpec& sweep, const SweepOptions& options);

/// Where trial `index` of configuration `config_id` lives under a sweep directory.
std::filesystem::path trialPath(const std::filesystem::path& out_dir, const std::string& config_id,
                                int index);

/// Every finished trial under a sweep directory, grouped by configuration in sweep order.
struct SweepResults {
  SweepSpec sweep;
  std::vector<SweepConfig> configs;
  std::vector<std::vector<TrialResult>> trials;  // [config][trial]
};
SweepResults loadSweepResults(const std::filesystem::path& out_dir, const LoadOptions& load = {});

/// summary.json of a sweep directory: per configuration its overrides, the trials finished, and
/// means over trials and steps of OSPA (m), Σ tr(P_pos) (m²) and the fraction of targets visible
/// to some UAV. Depends only on the finished trials, never on how they were run or resumed.
std::string summariseSweep(const SweepResults& results);

}  // namespace canopy::scenarios
