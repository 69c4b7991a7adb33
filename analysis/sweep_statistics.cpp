#include "analysis/sweep_statistics.h"

#include <algorithm>
#include <limits>
#include <tuple>

namespace canopy::analysis {

double ConfigStatistics::stateFraction(const std::string& state, int c) const {
  const auto it = std::find(states.begin(), states.end(), state);
  if (it == states.end() || trials == 0) return 0.0;
  return static_cast<double>(state_counts[c][it - states.begin()]) / trials;
}

Estimate ConfigStatistics::stateEstimate(const std::string& state, int c) const {
  const auto it = std::find(states.begin(), states.end(), state);
  if (it == states.end()) return proportion(0, trials);
  return proportion(state_counts[c][it - states.begin()], trials);
}

int ConfigStatistics::reachedBy(const std::string& state, int step) const {
  const auto named = std::find(states.begin(), states.end(), state) - states.begin();
  int reached = 0;
  for (const std::vector<int>& first : first_step_in) {
    reached += named < static_cast<long>(first.size()) && first[named] >= 0 && first[named] <= step;
  }
  return reached;
}

std::vector<double> ConfigStatistics::trialCoverageOver(int target, const Interval& steps) const {
  std::vector<double> means;
  for (const auto& coverage_t : trial_coverage) {
    double sum = 0.0;
    for (int k = steps.first; k <= steps.last; ++k) sum += coverage_t[target][k];
    means.push_back(sum / (steps.last - steps.first + 1));
  }
  return means;
}

Estimate ConfigStatistics::coverageOver(int target, const Interval& steps) const {
  return boundedMeanOf(trialCoverageOver(target, steps), 0.0, std::max(uavs, 1));
}

std::string ConfigStatistics::axisValue(const std::string& path) const {
  for (const std::string& p : point) {
    if (p.rfind(path + "=", 0) == 0) return p.substr(path.size() + 1);
  }
  for (auto it = overrides.rbegin(); it != overrides.rend(); ++it) {
    if (it->rfind(path + "=", 0) == 0) return it->substr(path.size() + 1);
  }
  return "";
}

int firstBelow(const std::vector<double>& curve, double threshold, int from) {
  for (int k = std::max(0, from); k < static_cast<int>(curve.size()); ++k) {
    if (curve[k] < threshold) return k;
  }
  return -1;
}

ConfigStatistics summarise(const std::vector<experiments::TrialResult>& trials,
                           const spec::ScenarioSpec& spec, const std::string& id,
                           const std::vector<std::string>& overrides) {
  ConfigStatistics stats;
  stats.id = id;
  stats.overrides = overrides;
  stats.trials = static_cast<int>(trials.size());
  stats.dt = spec.dt;
  for (const auto& named : spec.analysis.states) stats.states.push_back(named.name);
  for (const char* fallback : {"Miss 1", "Miss >1", "Other"}) stats.states.push_back(fallback);
  const std::size_t n_states = stats.states.size();
  for (auto& counts : stats.state_counts) counts.assign(n_states, 0);
  for (auto& flow : stats.flows) flow.assign(n_states, std::vector<int>(n_states, 0));
  if (trials.empty()) return stats;

  const int steps = trials.front().steps();
  const int targets = trials.front().targets;
  stats.uavs = trials.front().uavs;
  stats.columns = sankeyColumns(steps - 1);
  stats.coverage.assign(targets, std::vector<double>(steps, 0.0));
  stats.ospa.assign(steps, 0.0);
  stats.trace.assign(steps, 0.0);
  auto stateIndex = [&](const std::string& s) {
    return static_cast<std::size_t>(std::find(stats.states.begin(), stats.states.end(), s) -
                                    stats.states.begin());
  };
  std::vector<std::vector<SampleMoments>> coverage(targets, std::vector<SampleMoments>(steps));
  std::vector<SampleMoments> ospa(steps), trace(steps), team_ospa(steps), held(steps);
  const bool team_figures = std::all_of(trials.begin(), trials.end(), [](const auto& trial) {
    return !trial.team_ospa.empty();
  });

  for (const experiments::TrialResult& trial : trials) {
    const TrialBehaviour b = analyseTrial(trial, spec);
    stats.trial_seeds.push_back(trial.seed);
    std::array<int, 5>& columns = stats.trial_states.emplace_back();
    for (int c = 0; c < 5; ++c) {
      columns[c] = static_cast<int>(stateIndex(b.states[c]));
      ++stats.state_counts[c][columns[c]];
    }
    stats.first_step_in.push_back(b.first_step_in);
    for (int g = 0; g < 4; ++g)
      ++stats.flows[g][stateIndex(b.states[g])][stateIndex(b.states[g + 1])];
    for (const OwnershipChange& change : b.changes) {
      auto it = std::find_if(stats.changes.begin(), stats.changes.end(),
                             [&](const ChangeCount& c) { return c.change == change; });
      if (it == stats.changes.end()) it = stats.changes.insert(stats.changes.end(), {change, 0});
      ++it->trials;
    }
    for (const OcclusionEpisode& e : b.occlusions) {
      auto it = std::find_if(stats.occlusions.begin(), stats.occlusions.end(),
                             [&](const OcclusionStatistics& o) {
                               return o.target == e.target && o.hidden == e.hidden;
                             });
      if (it == stats.occlusions.end()) {
        it = stats.occlusions.insert(stats.occlusions.end(), OcclusionStatistics{});
        it->target = e.target;
        it->hidden = e.hidden;
      }
      ++it->trials;
      it->aware += e.aware;
      it->with_event += e.tree_seen_before;
      it->aware_with_event += e.aware && e.tree_seen_before;
    }
    for (int t = 0; t < targets; ++t) {
      for (int k = 0; k < steps; ++k) coverage[t][k].add(b.coverage[t][k]);
    }
    for (int k = 0; k < steps; ++k) {
      ospa[k].add(trial.ospa[k]);
      trace[k].add(trial.trace[k]);
      if (team_figures) {
        team_ospa[k].add(trial.team_ospa[k]);
        held[k].add(trial.held[k]);
      }
    }
    stats.trial_coverage.push_back(b.coverage);
    if (team_figures && steps > 0) {  // Σ_k x_k / K over the trial's steps
      double ospa_sum = 0.0, held_sum = 0.0;
      for (int k = 0; k < steps; ++k) {
        ospa_sum += trial.team_ospa[k];
        held_sum += trial.held[k];
      }
      stats.trial_team_ospa.push_back(ospa_sum / steps);
      stats.trial_held.push_back(held_sum / steps);
    }
  }
  stats.coverage_ci.assign(targets, std::vector<ConfidenceInterval>(steps));
  stats.ospa_ci.resize(steps);
  stats.trace_ci.resize(steps);
  for (int k = 0; k < steps; ++k) {
    for (int t = 0; t < targets; ++t) {
      stats.coverage[t][k] = coverage[t][k].mean();
      stats.coverage_ci[t][k] = boundedMeanInterval(coverage[t][k], 0.0, std::max(stats.uavs, 1));
    }
    stats.ospa[k] = ospa[k].mean();
    const double unbounded = std::numeric_limits<double>::infinity();
    stats.ospa_ci[k] = clipped(meanInterval(ospa[k]), 0.0, unbounded);
    stats.trace[k] = trace[k].mean();
    stats.trace_ci[k] = clipped(meanInterval(trace[k]), 0.0, unbounded);
    if (!team_figures) continue;
    stats.team_ospa.push_back(team_ospa[k].mean());
    stats.team_ospa_ci.push_back(clipped(meanInterval(team_ospa[k]), 0.0, unbounded));
    stats.held.push_back(held[k].mean());
    stats.held_ci.push_back(boundedMeanInterval(held[k], 0.0, 1.0));
  }
  std::sort(stats.changes.begin(), stats.changes.end(),
            [](const ChangeCount& a, const ChangeCount& b) {
              return std::tie(a.change.from, a.change.to, a.change.target) <
                     std::tie(b.change.from, b.change.to, b.change.target);
            });
  std::sort(stats.occlusions.begin(), stats.occlusions.end(),
            [](const OcclusionStatistics& a, const OcclusionStatistics& b) {
              return std::tie(a.target, a.hidden.first) < std::tie(b.target, b.hidden.first);
            });
  return stats;
}

}  // namespace canopy::analysis
