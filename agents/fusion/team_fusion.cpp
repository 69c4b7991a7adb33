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
  setPool(nullptr);
}

void TeamFusion::setPool(TaskPool* pool) {
  pool_ = pool;
  const std::size_t parts = pool != nullptr ? static_cast<std::size_t>(pool->threads()) : 1;
  target_consensus_.resize(parts);
  tree_consensus_.resize(parts);
  part_diagnostics_.resize(parts);
}

template <int N>
void TeamFusion::agree(std::vector<InformationConsensus<N>>& parts,
                       std::span<std::vector<tracking::Track<N>>> lists, const Clusters& clusters) {
  // Part p takes the clusters whose first member lies in [p·M/P, (p+1)·M/P), M members in all.
  const std::size_t count = parts.size();
  const auto members = static_cast<long>(clusters.members.size());
  auto boundary = [&](std::size_t p) {
    if (p == count) return clusters.size();
    const long member = members * static_cast<long>(p) / static_cast<long>(count);
    const auto start = clusters.start.begin();
    return static_cast<int>(std::lower_bound(start, start + clusters.size(), member) - start);
  };
  forEachTask(pool_, count, [&](std::size_t p) {
    part_diagnostics_[p] = {};
    parts[p].run(lists, clusters, boundary(p), boundary(p + 1), graph_, config_,
                 part_diagnostics_[p]);
  });
  for (const FusionDiagnostics& part : part_diagnostics_) diagnostics_ += part;
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
  // Each agent's lists copied on the pool (each task writes its own agent's entries).
  forEachTask(pool_, static_cast<std::size_t>(agents_), [&](std::size_t i) {
    positions_[i] = agents[i].position;
    fused.targets[i].assign(agents[i].targets.begin(), agents[i].targets.end());
    fused.trees[i].assign(agents[i].trees.begin(), agents[i].trees.end());
  });
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
                                target_clusters_, diagnostics_, pool_);
  agree<4>(target_consensus_, fused.targets, target_clusters_);
  tree_association_.associate(fused.trees, graph_, config_.association_gate, mint_, tree_clusters_,
                              diagnostics_, pool_);
  agree<3>(tree_consensus_, fused.trees, tree_clusters_);
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
