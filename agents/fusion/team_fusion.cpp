#include "agents/fusion/team_fusion.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <utility>

#include "agents/tracking/motion_model.h"

namespace canopy::agents::fusion {

TeamFusion::TeamFusion(const FusionConfig& config, int agents, std::uint64_t seed, double dt,
                       double sigma_a)
    : config_(config), dt_(dt), sigma_a_(sigma_a), agents_(std::max(agents, 0)), mint_(agents_) {
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
  if (config_.comm_latency > 0) {
    fuseLate(agents, fused);
    return;
  }
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
  ++step_;
  associateAndAgree(fused);
}

void TeamFusion::associateAndAgree(FusedTracks& fused) {
  target_association_.associate(fused.targets, graph_, config_.association_gate, mint_,
                                target_clusters_, diagnostics_);
  target_consensus_.run(fused.targets, target_clusters_, graph_, config_, diagnostics_);
  tree_association_.associate(fused.trees, graph_, config_.association_gate, mint_, tree_clusters_,
                              diagnostics_);
  tree_consensus_.run(fused.trees, tree_clusters_, graph_, config_, diagnostics_);
  shareOutlines(fused.trees, tree_clusters_, graph_, outline_scratch_);
}

void TeamFusion::fuseLate(std::span<const AgentTracks> agents, FusedTracks& fused) {
  const int k = config_.comm_latency;
  const std::size_t n = static_cast<std::size_t>(agents_);
  sent_.resize(static_cast<std::size_t>(k) + 1);
  // This step's lists go out now; the ones sent at step − k arrive now (another slot for k ≥ 1).
  FusedTracks& outgoing = sent_[static_cast<std::size_t>(step_ % (k + 1))];
  const FusedTracks& arriving = sent_[static_cast<std::size_t>((step_ + 1) % (k + 1))];
  const bool due = step_ >= k;  // anything sent yet that is due now
  outgoing.targets.resize(n);
  outgoing.trees.resize(n);
  for (std::size_t j = 0; j < n; ++j) {
    positions_[j] = agents[j].position;
    outgoing.targets[j].assign(agents[j].targets.begin(), agents[j].targets.end());
    outgoing.trees[j].assign(agents[j].trees.begin(), agents[j].trees.end());
  }
  graph_.build(positions_, config_.comm_range);
  const int exchanges = config_.method == FusionMethod::observer_average ? 1 : config_.rounds;
  graph_.drawLosses(exchanges, config_.comm_drop, loss_streams_);
  ++diagnostics_.steps;
  if (due) {
    diagnostics_.messages += graph_.messages();
    diagnostics_.lost_messages += graph_.lostMessages();
    diagnostics_.late_messages += graph_.messages() - graph_.lostMessages();
  }

  view_.targets.resize(n);
  view_.trees.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) {
      if (j == i) {
        view_.targets[j].assign(agents[j].targets.begin(), agents[j].targets.end());
        view_.trees[j].assign(agents[j].trees.begin(), agents[j].trees.end());
        continue;
      }
      view_.targets[j].clear();
      view_.trees[j].clear();
      if (!due) continue;
      view_.targets[j] = arriving.targets[j];
      view_.trees[j] = arriving.trees[j];  // trees are static: nothing to predict
      for (tracking::TargetTrack& track : view_.targets[j]) {  // x̄ = F(kΔt) x, P̄ = F P Fᵀ + Q
        track.posterior = tracking::predictNcv(track.posterior, k * dt_, sigma_a_);
        track.prior = track.posterior;
      }
    }
    associateAndAgree(view_);
    std::swap(fused.targets[i], view_.targets[i]);
    std::swap(fused.trees[i], view_.trees[i]);
  }
  ++step_;
}

}  // namespace canopy::agents::fusion
