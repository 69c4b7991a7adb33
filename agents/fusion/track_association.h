#pragma once
// Track-to-track association across the team for one step (algorithms.md §5): neighbours'
// tracks are matched (tracks that share a key first, then a gated Hungarian assignment on the
// rest), grouped into clusters (one target each, at most one track per agent), given one key
// each, and shared with neighbours that lack them.
#include <span>
#include <vector>

#include "agents/belief.h"
#include "agents/fusion/comm_graph.h"
#include "agents/fusion/fusion_diagnostics.h"
#include "agents/fusion/hungarian.h"
#include "agents/tracking/track.h"
#include "core/types.h"

namespace canopy::agents::fusion {

/// Fresh keys for a cluster that lost its key to another one: {agent, −1}, {agent, −2}, ...
/// Negative serials keep them apart from the tracker's serials (≥ 0) and from the scenario's
/// pre-seeded keys {−1, t}.
class KeyMint {
 public:
  explicit KeyMint(int agents = 0) : minted_(static_cast<std::size_t>(agents), 0) {}
  TrackKey next(int agent) { return {agent, -(++minted_[agent])}; }

 private:
  std::vector<int> minted_;  // keys minted so far, per agent
};

/// One agent's track inside a cluster.
struct ClusterMember {
  int agent = 0;
  int track = 0;         // index in the agent's list
  bool adopted = false;  // copied to this agent this step: it carries no measurement of its own
};

/// This step's clusters: each is one target as the team sees it, with at most one track per
/// agent, all carrying the cluster's key.
struct Clusters {
  std::vector<int> start;              // CSR: cluster c is members[start[c], start[c + 1])
  std::vector<ClusterMember> members;  // ascending agent within each cluster
  std::vector<TrackKey> keys;          // per cluster

  int size() const { return static_cast<int>(keys.size()); }
  std::span<const ClusterMember> of(int c) const {
    return {members.data() + start[c], static_cast<std::size_t>(start[c + 1] - start[c])};
  }
};

/// Association for one kind of track (targets: N = 4, trees: N = 3). Only the position block
/// (first two states) is compared: d² = Δpᵀ (P_i + P_j)⁻¹ Δp on the posteriors.
///
/// Rules, in order:
/// 1. Links exist only between neighbours of the graph (range); association messages are
///    treated as reliable, comm_drop acts on the consensus exchanges.
/// 2. On each link, tracks that share a key and a label stay matched while d² ≤ gate
///    (memory across steps); the others are assigned by GatedAssignment, per label, per
///    connected component of the gating graph, so a pair with d² > gate is never matched.
/// 3. Matches join clusters by union-find, remembered ones first, then the assigned ones by
///    increasing d²; a union that would give one agent two tracks in a cluster is refused.
/// 4. A cluster takes the smallest key of its members. If two clusters of one connected part of
///    the network would take the same key (tracks that share a key but drifted out of the gate),
///    the larger keeps it (ties: the one holding the lowest agent) and the other gets a fresh key.
/// 5. A cluster with a confirmed member is copied to every neighbour of a member that has no track
///    in it (from its lowest-numbered neighbour in the cluster: key, label, prior, posterior,
///    scans and hits; status confirmed; detected false). Adoption reaches one hop per step.
template <int N>
class TrackAssociation {
 public:
  using TrackList = std::vector<tracking::Track<N>>;

  /// lists[i]: agent i's tracks (the fusion's own copy, being fused). Rewrites keys, appends
  /// adopted copies, and fills `clusters`.
  void associate(std::span<TrackList> lists, const CommGraph& graph, double gate, KeyMint& mint,
                 Clusters& clusters, FusionDiagnostics& diagnostics);

 private:
  struct Node {
    TrackKey key;
    sensing::LabelId label = 0;
    int agent = 0;
    int track = 0;
    bool confirmed = false;
    Vec2 p = Vec2::Zero();  // m, posterior position
    Mat2 S = Mat2::Zero();  // m², its covariance
  };
  struct Link {
    double cost = 0.0;  // d²
    int a = 0;          // nodes
    int b = 0;
  };
  struct Gated {  // a gated pair of one link, in row / column indices of that link
    int row = 0;
    int col = 0;
    double cost = 0.0;
  };
  struct Adoption {
    int cluster = 0;
    int agent = 0;   // the adopter
    int source = 0;  // node copied
  };

  void gatherNodes(std::span<const TrackList> lists);
  void linkNeighbours(int i, int j, double gate);
  void assignComponents(double gate);
  void cluster(FusionDiagnostics& diagnostics);
  void chooseKeys(const CommGraph& graph, KeyMint& mint, FusionDiagnostics& diagnostics);
  void planAdoptions(const CommGraph& graph);
  void writeOut(std::span<TrackList> lists, Clusters& clusters, FusionDiagnostics& diagnostics);
  int find(int node);
  bool unite(int a, int b);

  int agents_ = 0;
  int mask_words_ = 1;           // 64-bit words per agent set
  std::vector<int> node_start_;  // CSR: nodes of agent a are [node_start_[a], node_start_[a + 1])
  std::vector<Node> nodes_;
  std::vector<int> by_key_;  // per agent, its nodes sorted by key
  std::vector<int> taken_;   // stamp: node matched by key on the current link
  int link_stamp_ = 0;
  std::vector<Link> remembered_;
  std::vector<Link> assigned_;
  std::vector<int> rows_, cols_;  // the current link's unmatched nodes of i and of j
  std::vector<Gated> gated_;
  std::vector<int> local_parent_;  // union-find over rows_ then cols_
  std::vector<int> row_slot_, col_slot_, group_rows_, group_cols_;
  std::vector<double> cost_;
  std::vector<AssignedPair> pairs_;
  GatedAssignment assignment_;
  std::vector<int> parent_;             // union-find over nodes
  std::vector<std::uint64_t> mask_;     // agents in each root's set (mask_words_ per node)
  std::vector<int> cluster_of_;         // per node
  std::vector<int> root_cluster_;       // per root node: its cluster, or −1
  std::vector<TrackKey> keys_;          // per cluster
  std::vector<int> first_node_, size_;  // per cluster
  std::vector<char> confirmed_;         // per cluster
  std::vector<int> order_;
  std::vector<Adoption> adoptions_;
};

}  // namespace canopy::agents::fusion
