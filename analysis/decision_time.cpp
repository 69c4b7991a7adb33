#include "analysis/decision_time.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "experiments/trial.h"

namespace canopy::analysis {

DecisionTime summariseDecisionTimes(const std::vector<std::vector<double>>& seconds_per_trial) {
  DecisionTime t;
  std::vector<double> all, trial_means;
  for (const std::vector<double>& trial : seconds_per_trial) {
    if (trial.empty()) continue;
    double sum = 0.0;
    for (const double s : trial) {
      all.push_back(1e6 * s);
      sum += 1e6 * s;
    }
    trial_means.push_back(sum / static_cast<double>(trial.size()));
  }
  t.trials = static_cast<int>(trial_means.size());
  t.calls = static_cast<int>(all.size());
  if (all.empty()) return t;
  // The mean of the trials' own means, with its Student-t interval (the mean over every call when
  // every trial makes as many calls). A time is never negative: the interval is cut at 0 (few
  // trials with one slow call spread it).
  const Estimate over_trials = meanOf(trial_means);
  t.mean_us = {over_trials.value,
               clipped(over_trials.ci, 0.0, std::numeric_limits<double>::infinity()), t.trials};
  std::sort(all.begin(), all.end());
  const std::size_t n = all.size();
  // Median: the middle call, or the mean of the two middle ones.
  t.median_us = n % 2 ? all[n / 2] : 0.5 * (all[n / 2 - 1] + all[n / 2]);
  // 90th percentile, nearest rank: the ⌈0.9·n⌉-th smallest.
  const auto rank = static_cast<std::size_t>(std::ceil(0.9 * static_cast<double>(n)));
  t.p90_us = all[std::max<std::size_t>(rank, 1) - 1];
  t.max_us = all.back();
  return t;
}

DecisionTime timeDecisions(const spec::ScenarioSpec& spec,
                           const std::vector<std::uint64_t>& seeds) {
  std::vector<std::vector<double>> seconds;
  for (const std::uint64_t seed : seeds) {
    spec::ScenarioSpec trial = spec;
    trial.seed = seed;
    seconds.push_back(experiments::runTrial(trial, "timing").plan_seconds);
  }
  return summariseDecisionTimes(seconds);
}

}  // namespace canopy::analysis
