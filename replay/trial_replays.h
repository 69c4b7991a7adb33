#pragma once
// `canopy analyze`'s replays: for every configuration of a sweep and every ownership state at the
// last step L that its trials reached (the behaviour classes of the Sankey diagram's last
// column), the first trial in that state run again (the same scenario and seed give the same
// run) into a run folder with its replay.html; and for each of those trials of a configuration
// after the first, the same trial (the same seed: a sweep gives trial i of every configuration
// one seed) of the first configuration beside it on one clock (side_by_side.html). One index
// page links them all.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "analysis/sweep_analysis.h"

namespace canopy::replay {

struct TrialReplay {
  std::string config;  // the sweep configuration's id
  std::string state;   // the ownership state at L, e.g. "M*", "Miss 1"
  int trials_in_state = 0, trials = 0;
  int trial = 0;               // the trial's place in its configuration (0 …)
  std::uint64_t seed = 0;      // its seed
  std::filesystem::path page;  // the replay, relative to the analysis folder
};

/// The same trial under two configurations, side by side.
struct TrialPair {
  std::string config_a, config_b;  // the first configuration, and the other one
  std::string state_a, state_b;    // the trial's ownership state at L under each
  int trial = 0;
  std::uint64_t seed = 0;
  std::filesystem::path page;  // side_by_side.html, relative to the analysis folder
};

struct TrialReplays {
  std::vector<TrialReplay> replays;  // one per class, in configuration then state order
  std::vector<TrialPair> pairs;      // one per replay of a configuration after the first
};

/// Runs the trials again into out_dir/replays/… and writes out_dir/replays.html. Throws
/// std::logic_error when a trial run again does not end in the state its trial file recorded
/// (the run would not be the trial).
TrialReplays writeTrialReplays(const analysis::SweepAnalysis& analysis,
                               const std::filesystem::path& out_dir);

}  // namespace canopy::replay
