#pragma once
// Track-to-track association across the team for one step (algorithms.md §5): neighbours'
// tracks are matched (tracks that share a key first, then a gated Hungarian assignment on the
// rest), grouped into clusters (one target each, at most one track per agent), given one key
// each, and shared with neighbours that lack them.
#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

#include "agents/belief.h"
#include "agents/fusion/comm_graph.h"
#include "agents/fusion/fusion_diagnostics.h"
#include "agents/fusion/hungarian.h"
#include "agents/tracking/track.h"
#include "core/task_pool.h"
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
///
/// Work. Rule 2's memory looks at every pair of neighbours' copies of a key: O(U² M) for U agents
/// that all hold M tracks. From `grouped_from` agents on, when no agent holds two tracks with one
/// key, the copies of each key are taken together instead (linkByKey): the copies near their
/// centre pass the gate by a bound (association_gate.h) and are joined per connected part of the
/// graph with bit sets, O(K · U/64) for K copies; only pairs with a copy outside that core are
/// computed. The links, clusters and counters are the same as pair by pair (remembered links never
/// conflict then: a set of one key's copies holds each agent at most once), so the result is too.
template <int N>
class TrackAssociation {
 public:
  using TrackList = std::vector<tracking::Track<N>>;
  static constexpr int kGroupedFrom = 8;  // agents; a paper team's few pairs are cheaper one by one

  explicit TrackAssociation(int grouped_from = kGroupedFrom) : grouped_from_(grouped_from) {}

  /// lists[i]: agent i's tracks (the fusion's own copy, being fused). Rewrites keys, appends
  /// adopted copies, and fills `clusters`. With a pool, each agent's tracks are gathered on it
  /// (the same result).
  void associate(std::span<TrackList> lists, const CommGraph& graph, double gate, KeyMint& mint,
                 Clusters& clusters, FusionDiagnostics& diagnostics, TaskPool* pool = nullptr);

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

  void gatherNodes(std::span<const TrackList> lists, TaskPool* pool);
  void startUnionFind();
  void gatherNeighbourSets(const CommGraph& graph);  // neighbours_ of this step's graph
  // An agent's bit in its word of an agent set.
  static std::uint64_t bitOf(int agent) { return std::uint64_t{1} << (agent % 64); }
  // Whether the agent set starting at `set` (mask_words_ words) holds `agent`.
  static bool holds(const std::uint64_t* set, int agent) {
    return (set[agent / 64] & bitOf(agent)) != 0;
  }
  bool keysUniquePerAgent() const;
  // Rule 2 pair by pair: the shared keys on link i–j, then the rest (gateAndAssign).
  void linkNeighbours(int i, int j, double gate);
  // Rule 2 by key (track_association_by_key.cpp): every remembered link of the step, joined at
  // once; then per link only the copies without a partner there (linkUnmatched).
  void linkByKey(double gate, FusionDiagnostics& diagnostics);
  void linkKey(std::span<const int> copies, double gate);
  void joinPart(int start_agent, std::span<std::uint64_t> remaining);
  void linkUnmatched(int i, int j, double gate);
  void gateAndAssign(double gate);
  void assignComponents(double gate);
  void cluster(FusionDiagnostics& diagnostics);
  void chooseKeys(const CommGraph& graph, KeyMint& mint, FusionDiagnostics& diagnostics);
  void planAdoptions();
  void writeOut(std::span<TrackList> lists, Clusters& clusters, FusionDiagnostics& diagnostics);
  int find(int node);
  bool unite(int a, int b);

  int grouped_from_ = kGroupedFrom;
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
  std::vector<std::uint64_t> neighbours_;  // per agent, its neighbours as a bit set
  // linkByKey's scratch.
  struct KeyLabel {
    std::uint64_t key = 0;  // TrackKey (origin, serial), packed
    sensing::LabelId label = 0;
    bool operator==(const KeyLabel&) const = default;
  };
  struct KeyLabelHash {
    std::size_t operator()(const KeyLabel& k) const noexcept {
      const std::uint64_t h = (k.key ^ static_cast<std::uint32_t>(k.label)) * 0x9E3779B97F4A7C15ull;
      return static_cast<std::size_t>(h ^ (h >> 32));
    }
  };
  std::unordered_map<KeyLabel, int, KeyLabelHash> group_of_;  // (key, label) → its group
  std::vector<int> group_start_, group_nodes_;                // CSR: group g's nodes, ascending
  std::vector<int> node_group_, fill_;
  std::vector<std::uint64_t> partners_;           // per node, the agents it is remembered with
  std::vector<std::uint64_t> core_;               // the agents of the current key's core copies
  std::vector<int> copy_of_agent_;                // the current key's node per agent, or −1
  std::vector<int> outside_;                      // the current key's copies outside the core
  std::vector<int> stack_;                        // joinPart's agents to visit
  std::vector<int> unmatched_start_, unmatched_;  // CSR per agent: nodes short of a partner
  long remembered_links_ = 0;
};

}  // namespace canopy::agents::fusion
