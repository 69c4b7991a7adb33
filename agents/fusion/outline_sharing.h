#pragma once
// Fusion of crown outlines (trees only). The outline is not a Gaussian state, so consensus does
// not average it; instead each agent's track takes, from itself and its neighbours' tracks of the
// same cluster, the outline averaged over the most measurements. Like the association exchange
// it is taken as reliable; like consensus it reaches one hop per step.
#include <span>
#include <vector>

#include "agents/fusion/comm_graph.h"
#include "agents/fusion/track_association.h"
#include "agents/tracking/track.h"

namespace canopy::agents::fusion {

/// trees[i]: agent i's fused tree list, clustered by `clusters` over `graph`.
void shareOutlines(std::vector<std::vector<tracking::TreeTrack>>& trees, const Clusters& clusters,
                   const CommGraph& graph, std::vector<tracking::TreeOutline>& scratch);

}  // namespace canopy::agents::fusion
