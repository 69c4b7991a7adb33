#pragma once
// The team's fusion step (algorithms.md §5): once per simulation step, after every agent's local
// tracking update, on all agents' track lists at once. Messages are simulated, so the one object
// that sees every list plays the network; each agent still uses only what its neighbours sent.
#include <cstdint>
#include <span>
#include <vector>

#include "agents/config.h"
#include "agents/fusion/comm_graph.h"
#include "agents/fusion/fusion_diagnostics.h"
#include "agents/fusion/information_consensus.h"
#include "agents/fusion/outline_sharing.h"
#include "agents/fusion/track_association.h"
#include "agents/tracking/track.h"
#include "core/random.h"
#include "core/task_pool.h"
#include "core/types.h"

namespace canopy::agents::fusion {

/// One agent's part in a fusion step, read only: its lists after this step's local tracking and
/// its position.
struct AgentTracks {
  std::span<const tracking::TargetTrack> targets;  // OOI tracks
  std::span<const tracking::TreeTrack> trees;      // SOO tracks, its map Ŵ_i
  Vec2 position = Vec2::Zero();                    // m, UAV ground position (comm_range)
};

/// The result of a fusion step: every agent's lists after it, by agent index, for the agent to
/// adopt as its own.
struct FusedTracks {
  std::vector<std::vector<tracking::TargetTrack>> targets;  // [agent]
  std::vector<std::vector<tracking::TreeTrack>> trees;      // [agent]
};

/// Distributed fusion of the whole team, targets (Track<4>) and trees (Track<3>) alike.
///
/// fuse(agents, fused), with agents[i] agent i (size = the team size given at construction), reads
/// every agent's lists and writes the fused lists into `fused`; the agents' own lists are not
/// touched (each agent adopts its fused lists afterwards, Agent::adoptFused). fused.targets[i]
/// starts as a copy of agents[i].targets (fused.trees[i] likewise) and is then changed by:
/// 1. Graph: UAVs within config.comm_range (m) of each other are neighbours (all pairs when
///    infinite), with Metropolis weights π_ij = 1 / (1 + max(deg_i, deg_j)). For each of the
///    L = config.rounds consensus exchanges (one for observer_average) every directed message is
///    lost with probability config.comm_drop, drawn from agent i's own stream for the messages it
///    receives ("fusion.loss", index i). A lost message's weight goes to the receiver's own value
///    (see InformationConsensus). The association exchange is taken as reliable.
/// 2. Association (TrackAssociation): neighbours' tracks are matched by label and position
///    (χ²₂ gate config.association_gate, Hungarian assignment, tracks sharing a key kept together
///    while gated); matched tracks take the smallest key; a confirmed track a neighbour lacks is
///    copied into the neighbour's fused list (appended), so it reaches one more hop every step.
/// 3. Consensus (InformationConsensus) by config.method: every track's posterior is overwritten
///    by the fused one. A tree's outline is not averaged: each takes its neighbours' outline
///    with the most measurements (shareOutlines). Track::prior, status and the counters are left alone, except that
///    adopted copies are confirmed, with detected = false.
///
/// 4. Latency: with config.comm_latency = k > 0 a consensus message reaches its receiver k steps
///    after it was sent. Receiver i then fuses its own lists of this step with the lists each
///    neighbour held k steps before (targets predicted over k·dt by the NCV model with σ_a,
///    trees static), nothing from a neighbour during the first k steps. Each receiver's view
///    differs, so steps 2–3 run once per receiver on its view and it keeps its own fused lists;
///    the graph (current positions) and the losses are drawn once per step, and messages are
///    counted when due (sent, lost, late). The association and consensus counters add up over
///    the receivers' runs.
///
/// Postconditions: within one connected part of the network no two clusters share a key, so no
/// fused list holds two tracks with one key; tracks never change label, and a fused list holds
/// its agent's tracks in their order, then the adopted ones (fusion deletes nothing: deletion
/// stays with the tracker). The fused lists of agents out of range of everyone equal their
/// input. The result depends only on the inputs, the seed and the number of fuse() calls
/// so far (the loss streams advance), never on timing.
///
/// Memory: scratch buffers are members, cleared and refilled every step, and the fused lists are
/// refilled in place, so a steady team whose caller keeps one FusedTracks allocates nothing per
/// step once warmed up (except to append adopted tracks). Not thread-safe;
/// one TeamFusion per simulated team.
class TeamFusion {
 public:
  /// config: validated at load time (rounds ≥ 0, comm_range > 0, comm_drop in [0, 1],
  /// comm_latency ≥ 0, association_gate > 0 and finite). agents: team size N ≥ 0. seed: the
  /// trial's seed. dt (s) and sigma_a (m/s², the trackers' NCV intensity) predict late messages.
  TeamFusion(const FusionConfig& config, int agents, std::uint64_t seed, double dt = 0.2,
             double sigma_a = 1.0);

  /// Runs one fusion step on the agents' lists and writes the result into `fused` (resized to
  /// the team; its lists' capacity is reused). agents.size() must equal the team size (checked:
  /// a mismatch is a programming error and aborts).
  void fuse(std::span<const AgentTracks> agents, FusedTracks& fused);

  /// Threads for the consensus: clusters are fused in as many parts as the pool has threads
  /// (nullptr: one part, on the caller's thread). The result does not depend on it.
  void setPool(TaskPool* pool);
  /// Totals since construction.
  const FusionDiagnostics& diagnostics() const { return diagnostics_; }
  /// The graph of the last step (neighbours, weights, losses), for recording and tests.
  const CommGraph& graph() const { return graph_; }
  const FusionConfig& config() const { return config_; }

 private:
  // Steps 2–3 (association, consensus, outlines) on `fused`, every agent's lists at once.
  void associateAndAgree(FusedTracks& fused);
  // Consensus on one kind of track, its clusters split into parts.size() runs of about equal
  // membership, the parts side by side.
  template <int N>
  void agree(std::vector<InformationConsensus<N>>& parts,
             std::span<std::vector<tracking::Track<N>>> lists, const Clusters& clusters);
  // fuse() with comm_latency > 0 (point 4 above).
  void fuseLate(std::span<const AgentTracks> agents, FusedTracks& fused);

  FusionConfig config_;
  double dt_ = 0.2;       // s
  double sigma_a_ = 1.0;  // m/s²
  int agents_ = 0;
  std::vector<RandomStream> loss_streams_;  // per agent: losses of the messages it receives
  KeyMint mint_;
  CommGraph graph_;
  FusionDiagnostics diagnostics_;
  std::vector<Vec2> positions_;
  TrackAssociation<4> target_association_;
  TrackAssociation<3> tree_association_;
  TaskPool* pool_ = nullptr;
  std::vector<InformationConsensus<4>> target_consensus_;  // one per part
  std::vector<InformationConsensus<3>> tree_consensus_;
  std::vector<FusionDiagnostics> part_diagnostics_;
  Clusters target_clusters_;
  Clusters tree_clusters_;
  std::vector<tracking::TreeOutline> outline_scratch_;
  // Latency: the lists each agent sent at the last k + 1 steps, [step % (k + 1)][agent].
  std::vector<FusedTracks> sent_;
  FusedTracks view_;  // one receiver's view: its own lists and its neighbours' late ones
  long step_ = 0;     // fuse() calls so far
};

}  // namespace canopy::agents::fusion
