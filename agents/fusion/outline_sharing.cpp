#include "agents/fusion/outline_sharing.h"

namespace canopy::agents::fusion {

void shareOutlines(std::vector<std::vector<tracking::TreeTrack>>& trees, const Clusters& clusters,
                   const CommGraph& graph, std::vector<tracking::TreeOutline>& scratch) {
  for (int c = 0; c < clusters.size(); ++c) {
    const std::span<const ClusterMember> members = clusters.of(c);
    // What each member held before this exchange (a member's pick must not see another's).
    scratch.clear();
    for (const ClusterMember& m : members) scratch.push_back(trees[m.agent][m.track].outline);
    if (graph.complete()) {
      // Everyone linked: member a keeps its own outline when no other has more observations, and
      // otherwise takes the first (lowest member) with the most, as the loop below would pick.
      std::size_t first_most = 0;
      for (std::size_t b = 1; b < members.size(); ++b)
        if (scratch[b].observations > scratch[first_most].observations) first_most = b;
      for (std::size_t a = 0; a < members.size(); ++a) {
        const bool own = scratch[a].observations >= scratch[first_most].observations;
        trees[members[a].agent][members[a].track].outline = scratch[own ? a : first_most];
      }
      continue;
    }
    for (std::size_t a = 0; a < members.size(); ++a) {
      std::size_t best = a;
      for (std::size_t b = 0; b < members.size(); ++b) {
        if (b == a || !graph.linked(members[a].agent, members[b].agent)) continue;
        if (scratch[b].observations > scratch[best].observations) best = b;
      }
      trees[members[a].agent][members[a].track].outline = scratch[best];
    }
  }
}

}  // namespace canopy::agents::fusion
