#pragma once
// Per-configuration statistics over a sweep's trials: ownership-state frequencies and flows at
// the Sankey columns, Ownership_Change counts, Occlusion_Aware frequencies (plain and given the
// occlusion-detection event), mean coverage curves, and OSPA / tr(P) over time — each mean with
// its 95 % interval, and the per-trial facts behind the report's intervals.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "analysis/intervals.h"
#include "analysis/trial_behaviour.h"
#include "experiments/trial.h"
#include "spec/scenario_spec.h"

namespace canopy::analysis {

struct OcclusionStatistics {
  int target = 0;
  Interval hidden;     // steps
  int trials = 0;      // trials with this interval
  int aware = 0;       // … judged Occlusion_Aware
  int with_event = 0;  // … where the hiding tree was seen before the window (event e)
  int aware_with_event = 0;
  double pAware() const { return trials ? static_cast<double>(aware) / trials : 0.0; }
  double pAwareGivenEvent() const {
    return with_event ? static_cast<double>(aware_with_event) / with_event : 0.0;
  }
  Estimate awareEstimate() const { return proportion(aware, trials); }
  Estimate awareGivenEventEstimate() const { return proportion(aware_with_event, with_event); }
};

struct ChangeCount {
  OwnershipChange change;
  int trials = 0;  // trials with this change from k = 0 to k = L
};

struct ConfigStatistics {
  std::string id;                      // the sweep configuration
  std::vector<std::string> overrides;  // its --set values
  std::vector<std::string> point;      // per sweep axis "path-or-name=value" (SweepConfig::point)
  int trials = 0;
  int uavs = 0;
  double dt = 0.2;                               // s
  std::array<int, 5> columns{};                  // steps of the Sankey columns
  std::vector<std::string> states;               // named states, then "Miss 1", "Miss >1", "Other"
  std::array<std::vector<int>, 5> state_counts;  // [column][state]
  std::array<std::vector<std::vector<int>>, 4> flows;  // [gap][from][to] trial counts
  std::vector<ChangeCount> changes;
  std::vector<OcclusionStatistics> occlusions;
  std::vector<std::vector<double>> coverage;  // [t][k]: mean number of footprints holding t
  std::vector<double> ospa;                   // [k]: mean OSPA (m)
  // [k]: mean team OSPA (m) and fraction of people held, over the trials that carry them (all or
  // none: empty when a trial file predates them).
  std::vector<double> team_ospa, held;
  std::vector<ConfidenceInterval> team_ospa_ci, held_ci;
  std::vector<double> trace;                  // [k]: mean Σ tr(P_pos) (m²)
  // 95 % intervals inside what the quantity can take: coverage in [0, uavs] footprints by
  // boundedMeanInterval (t on the logit scale); OSPA and tr(P) ≥ 0, t intervals clipped at 0.
  std::vector<std::vector<ConfidenceInterval>> coverage_ci;  // [t][k]
  std::vector<ConfidenceInterval> ospa_ci, trace_ci;         // [k] (m, m²)

  // Per trial, in trial order.
  std::vector<std::array<int, 5>> trial_states;  // [trial][column]: index into states
  std::vector<std::uint64_t> trial_seeds;        // [trial]: its seed, to run it again
  std::vector<std::vector<int>> first_step_in;   // [trial][named state]: first step in it, −1
  std::vector<std::vector<std::vector<int>>> trial_coverage;  // [trial][t][k]: footprints on t
  // [trial]: its team OSPA (m) and fraction of people held, each averaged over the steps (empty
  // when the trial files predate the team figures).
  std::vector<double> trial_team_ospa, trial_held;

  /// The JSON text this configuration gives a sweep axis or --set path: its point on the axis
  /// named `path`, else its last override of `path` (axes come after fixed values); "" if none.
  std::string axisValue(const std::string& path) const;

  /// Fraction of trials in `state` at Sankey column c (0 if the state is unknown).
  double stateFraction(const std::string& state, int c) const;
  /// … with its Wilson interval.
  Estimate stateEstimate(const std::string& state, int c) const;
  /// Trials that were in the named `state` at some step k ≤ step (0 if it is not a named state).
  int reachedBy(const std::string& state, int step) const;
  /// Per trial, the mean number of footprints on target t over the inclusive steps of `steps`.
  std::vector<double> trialCoverageOver(int target, const Interval& steps) const;
  /// Their mean over trials with its 95 % interval inside [0, uavs] (boundedMeanOf).
  Estimate coverageOver(int target, const Interval& steps) const;
};

/// trials: all of one configuration (at least one); spec: that configuration's scenario.
ConfigStatistics summarise(const std::vector<experiments::TrialResult>& trials,
                           const spec::ScenarioSpec& spec, const std::string& id,
                           const std::vector<std::string>& overrides);

/// The first step ≥ from at which curve[k] < threshold, or −1.
int firstBelow(const std::vector<double>& curve, double threshold, int from = 0);

}  // namespace canopy::analysis
