#include "agents/fusion/team_fusion.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace canopy::agents::fusion {

TeamFusion::TeamFusion(const FusionConfig& config, int agents, std::uint64_t seed)
    : config_(config), agents_(std::max(agents, 0)), mint_(agents_) {
  loss_streams_.reserve(static_cast<std::size_t>(agents_));
  for (int i = 0; i < agents_; ++i) {
    loss_streams_.emplace_back(seed, "fusion.loss", static_cast<std::uint64_t>(i));
  }
  positions_.resize(static_cast<std::size_t>(agents_));
}

void TeamFusion::fuse(std::span<const AgentTracks> agents, FusedTracks& fused) {
  if (static_cast<int>(agents.size()) != agents_) {
    std::fprintf(stderr, "TeamFusion::fuse: %zu agents given, team has %d\n", agents.size(),
                 agents_);
    std::abort();
  }
  fused.targets.resize(static_cast<std::size_t>(agents_));
  fused.trees.resize(static_cast<std::size_t>(agents_));
  for (int i = 0; i < agents_; ++i) {
    positions_[i] = agents[i].position;
    fused.targets[i].assign(agents[i].targets.begin(), agents[i].targets.end());
    fused.trees[i].assign(agents[i].trees.begin(), agents[i].trees.end());
  }
  graph_.build(positions_, config_.comm_range);
  const int exchanges = config_.method == FusionMethod::observer_average ? 1 : config_.rounds;
  graph_.drawLosses(exchanges, config_.comm_drop, loss_streams_);
  ++diagnostics_.steps;
  diagnostics_.messages += graph_.messages();
  diagnostics_.lost_messages += graph_.lostMessages();

  target_association_.associate(fused.targets, graph_, config_.association_gate, mint_,
                                target_clusters_, diagnostics_);
  target_consensus_.run(fused.targets, target_clusters_, graph_, config_, diagnostics_);
  tree_association_.associate(fused.trees, graph_, config_.association_gate, mint_, tree_clusters_,
                              diagnostics_);
  tree_consensus_.run(fused.trees, tree_clusters_, graph_, config_, diagnostics_);
  shareOutlines(fused.trees, tree_clusters_, graph_, outline_scratch_);
}

}  // namespace canopy::agents::fusion
