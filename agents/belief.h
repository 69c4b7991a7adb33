#pragma once
// What one agent believes, as plain values: for the recorder, the renderer and the analysis.
#include <compare>
#include <vector>

#include "agents/gaussian.h"
#include "sensing/observation.h"

namespace canopy::agents {

/// A track's global key: the agent that started it and its serial number there. Matched tracks
/// adopt the smaller key, so keys converge across the team (algorithms.md §5).
struct TrackKey {
  int origin = -1;
  int serial = -1;
  friend auto operator<=>(const TrackKey&, const TrackKey&) = default;
};

/// A fused OOI track.
struct TrackEstimate {
  TrackKey key;
  sensing::LabelId label = 1;
  TargetGaussian belief;
  bool confirmed = false;
  double existence = 1.0;  // probability of existence (JIPDA, after fusion)
};

/// A fused tree track: one disc of the dynamic occlusion map Ŵ_i.
struct TreeEstimate {
  TrackKey key;
  TreeGaussian belief;      // centre (m) and crown radius (m)
  sensing::Outline outline;  // a polygonal crown's estimated vertex offsets (m); none: a disc
};

struct AgentBelief {
  std::vector<TrackEstimate> tracks;
  std::vector<TreeEstimate> trees;
  std::vector<Vec2> planned_path;  // m, the agent's planned positions p_{i,1..H} (empty if none)
};

}  // namespace canopy::agents
