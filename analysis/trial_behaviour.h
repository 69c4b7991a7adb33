#pragma once
// What one trial did, in the paper's terms: its ownership state at the Sankey columns, its
// Ownership_Change events, its Occlusion_Aware verdict for every occluded interval, the first step
// it was in each named state, and the coverage of every trajectory.
#include <array>
#include <string>
#include <vector>

#include "analysis/behaviours.h"
#include "experiments/trial.h"
#include "spec/scenario_spec.h"

namespace canopy::analysis {

/// The Sankey columns: k = 0, L/4, L/2, 3L/4, L (rounded to steps), L the last step.
std::array<int, 5> sankeyColumns(int last_step);

/// One occluded interval of one target and the Occlusion_Aware verdict on it.
struct OcclusionEpisode {
  int target = 0;
  Interval hidden;           // steps strictly under a crown
  int k0 = 0, L = 0, h = 0;  // the Occlusion_Aware window: [k0 + h, k0 + L − h] = hidden
  bool aware = false;
  int tree = -1;                  // the tree that hides the target (at the interval's first step)
  bool tree_seen_before = false;  // occlusion-detection event e: that tree was in some
                                  // footprint before k0
};

struct TrialBehaviour {
  std::array<std::string, 5> states;     // ownership state at each Sankey column
  std::vector<int> first_step_in;        // [named state]: first k whose state it is, −1 never
  std::vector<OwnershipChange> changes;  // from k = 0 to k = L
  std::vector<OcclusionEpisode> occlusions;
  std::vector<std::vector<int>> coverage;  // [t][k]: footprints holding target t
};

/// m, the named states and the Occlusion_Aware margin h (s, rounded to steps, shortened where
/// the trial's start or end cuts it) come from spec.analysis; the hiding tree from spec.
TrialBehaviour analyseTrial(const experiments::TrialResult& trial, const spec::ScenarioSpec& spec);

}  // namespace canopy::analysis
