#include "analysis/trial_behaviour.h"

#include <algorithm>
#include <bit>
#include <cmath>

namespace canopy::analysis {

std::array<int, 5> sankeyColumns(int last_step) {
  std::array<int, 5> columns{};
  for (int c = 0; c < 5; ++c) columns[c] = static_cast<int>(std::lround(last_step * c / 4.0));
  return columns;
}

namespace {

int hidingTree(const spec::ScenarioSpec& spec, int target, int step) {
  const Vec2 p = spec.targets[target].path.positionAt(step * spec.dt);
  for (int w = 0; w < static_cast<int>(spec.trees.size()); ++w) {
    if (world::strictlyInside(spec.trees[w], p)) return w;
  }
  return -1;
}

}  // namespace

TrialBehaviour analyseTrial(const experiments::TrialResult& trial, const spec::ScenarioSpec& spec) {
  TrialBehaviour out;
  const int K = trial.steps() - 1;
  const SetHistory M = mOwnership(trial.visible, spec.analysis.m);
  const std::array<int, 5> columns = sankeyColumns(K);
  for (int c = 0; c < 5; ++c)
    out.states[c] = ownershipState(M[columns[c]], spec.analysis.states, trial.targets);
  out.changes = ownershipChanges(M, 0, K, trial.targets);
  // The classifier of the Sankey columns, at every step: "reached M* by L/2" is first ≤ L/2.
  out.first_step_in.assign(spec.analysis.states.size(), -1);
  for (int k = 0; k <= K; ++k) {
    const std::string state = ownershipState(M[k], spec.analysis.states, trial.targets);
    for (std::size_t s = 0; s < spec.analysis.states.size(); ++s) {
      if (out.first_step_in[s] < 0 && spec.analysis.states[s].name == state)
        out.first_step_in[s] = k;
    }
  }

  const int margin = static_cast<int>(std::lround(spec.analysis.oa_margin / trial.dt));
  for (int t = 0; t < trial.targets; ++t) {
    for (const Interval& hidden : runsOf(trial.occluded, t)) {
      OcclusionEpisode episode;
      episode.target = t;
      episode.hidden = hidden;
      // The largest symmetric margin h ≤ oa_margin that fits inside the trial.
      episode.h = std::min({margin, hidden.first, K - hidden.last});
      episode.k0 = hidden.first - episode.h;
      episode.L = hidden.last - hidden.first + 2 * episode.h;
      episode.aware = occlusionAware(M, trial.in_footprint, trial.occluded, t, episode.k0,
                                     episode.L, episode.h);
      episode.tree = hidingTree(spec, t, hidden.first);
      if (episode.tree >= 0) {
        const int seen = trial.tree_first_seen[episode.tree];
        episode.tree_seen_before = seen >= 0 && seen < episode.k0;
      }
      out.occlusions.push_back(episode);
    }
  }

  out.coverage.assign(trial.targets, std::vector<int>(trial.steps(), 0));
  for (int k = 0; k < trial.steps(); ++k) {
    for (const TargetSet s : trial.in_footprint[k]) {
      for (int t = 0; t < trial.targets; ++t) out.coverage[t][k] += static_cast<int>((s >> t) & 1);
    }
  }
  return out;
}

}  // namespace canopy::analysis
