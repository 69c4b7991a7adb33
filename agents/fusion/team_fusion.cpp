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
  target_lists_.resize(static_cast<std::size_t>(agents_));
  tree_lists_.resize(static_cast<std::size_t>(agents_));
}

void TeamFusion::fuse(std::span<const AgentTracks> agents) {
  if (static_cast<int>(agents.size()) != agents_) {
    std::fprintf(stderr, "TeamFusion::fuse: %zu agents given, team has %d\n", agents.size(),
                 agents_);
    std::abort();
  }
  for (int i = 0; i < agents_; ++i) {
    positions_[i] = agents[i].position;
    target_lists_[i] = agents[i].targets;
    tree_lists_[i] = agents[i].trees;
  }
  graph_.build(positions_, config_.comm_range);
  const int exchanges = config_.method == FusionMethod::observer_average ? 1 : config_.rounds;
  graph_.drawLosses(exchanges, config_.comm_drop, loss_streams_);
  ++diagnostics_.steps;
  diagnostics_.messages += graph_.messages();
  diagnostics_.lost_messages += graph_.lostMessages();

  target_association_.associate(target_lists_, graph_, config_.association_gate, mint_,
                                target_clusters_, diagnostics_);
  target_consensus_.run(target_lists_, target_clusters_, graph_, config_, diagnostics_);
  tree_association_.associate(tree_lists_, graph_, config_.association_gate, mint_, tree_clusters_,
                              diagnostics_);
  tree_consensus_.run(tree_lists_, tree_clusters_, graph_, config_, diagnostics_);
}

}  // namespace canopy::agents::fusion
