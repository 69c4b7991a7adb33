#pragma once
// How long one agent's planning decision takes (issue 54): `canopy reproduce` runs the first few
// trials of each planner configuration again, one at a time on one thread, and times every
// planning call (one agent at one epoch, steady_clock around its search or its network; the
// AgentPlanReport's seconds), so that learned, SMA-NBO and Dec-POMDP are compared on the same
// decisions under the same load.
#include <cstdint>
#include <vector>

#include "analysis/intervals.h"
#include "spec/scenario_spec.h"

namespace canopy::analysis {

struct DecisionTime {
  int trials = 0;  // trials timed
  int calls = 0;   // planning calls in them (agents × epochs)
  // Mean per call (µs): the mean of the trials' own means (the mean over every call when every
  // trial makes as many calls), with its 95 % Student-t interval over them (calls within a trial
  // share its load and its states, so the trial is the independent unit), cut at 0.
  Estimate mean_us;
  double median_us = 0.0, p90_us = 0.0, max_us = 0.0;  // over every call (µs)
  bool timed() const { return calls > 0; }
};

/// The figures of per-trial lists of call times (s): the mean of the trials' means with its
/// interval, median and 90th percentile (nearest rank: the ⌈0.9·n⌉-th smallest) of all calls.
DecisionTime summariseDecisionTimes(const std::vector<std::vector<double>>& seconds_per_trial);

/// Runs `spec` once per seed, one trial at a time on the calling thread, and summarises every
/// planning call's wall time.
DecisionTime timeDecisions(const spec::ScenarioSpec& spec, const std::vector<std::uint64_t>& seeds);

}  // namespace canopy::analysis
