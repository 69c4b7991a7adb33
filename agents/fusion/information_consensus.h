#pragma once
// Consensus over this step's clusters, in information form (algorithms.md §5): consensus on
// information (CI), hybrid consensus on measurements and information (HCMCI), or the reference
// simulator's observer average.
#include <Eigen/Core>
#include <span>
#include <vector>

#include "agents/config.h"
#include "agents/fusion/comm_graph.h"
#include "agents/fusion/fusion_diagnostics.h"
#include "agents/fusion/track_association.h"
#include "agents/tracking/track.h"

namespace canopy::agents::fusion {

/// Consensus for one kind of track (targets: N = 4, trees: N = 3). Each cluster is fused on its
/// own, among its members; Ω = P⁻¹ and q = P⁻¹x are an agent's information pair.
///
/// A round is one message from every agent to every neighbour. Agent i mixes
///   y_i ← Σ_{j ∈ heard} π_ij y_j + (π_ii + Σ_{j ∉ heard} π_ij) y_i
/// where "heard" are the neighbours that hold a track in the cluster and whose message of this
/// round arrived: the weight of a missing or lost message goes to the agent's own value, so every
/// update is still a convex combination (weights ≥ 0 summing to 1), Ω stays positive definite and
/// CI's fused estimate stays consistent. With no losses the weights are symmetric and doubly
/// stochastic, so the team's mean is kept exactly and the rounds converge to it.
///
/// Methods (config.method):
/// - ci: y = (Ω, q) from the posterior; L = config.rounds rounds; P = Ω⁻¹, x = Ω⁻¹q.
/// - hcmci: y = (Ω⁻, q⁻, δΩ, δq) with Ω⁻ from Track::prior and δΩ = Ω_post − Ω⁻ (zero for a track
///   adopted this step: it holds no measurement of its own); L rounds; Ω = Ω⁻ + ω δΩ, with ω the
///   number of holders the agent's holder subgraph connects (the team size N on a complete graph
///   where all hold the track, which makes HCMCI the centralised filter there).
/// - observer_average: one exchange; an agent averages (Ω, q) over itself and the neighbours it
///   heard, counting only those that observed the target this step (Track::detected); with no
///   observer among them it keeps its own posterior. rounds is ignored.
/// Existence (JIPDA, Track::existence) is fused beside the state, as log-odds l = ln(r / (1 − r)):
/// ci mixes l over the same rounds (the normalised geometric mean of the members' Bernoulli
/// distributions, CI's rule for a Bernoulli); hcmci mixes (l⁻, l − l⁻) with l⁻ from
/// Track::existence_prior and sets l = l⁻ + ω (l − l⁻) (independent evidence, as for the
/// information); observer_average averages l over the same observers.
/// A member whose covariance cannot be inverted takes no part and keeps its posterior; a fused
/// information matrix that is not positive definite leaves the posterior unchanged. Both are
/// counted as numerical failures.
template <int N>
class InformationConsensus {
 public:
  /// From this many members on, CI on a complete graph without losses mixes in closed form
  /// (mixOnCompleteGraph); the paper's teams (2–4 UAVs) stay far below it.
  static constexpr std::size_t kClosedFormFrom = 16;
  /// From this many members, CI converts a run of members with the same bits once (runCi).
  static constexpr std::size_t kReuseFrom = 8;

  using TrackList = std::vector<tracking::Track<N>>;

  /// Overwrites the posterior of every member of every cluster with two or more members. Uses
  /// the losses drawn on `graph` (round r of consensus is exchange r).
  void run(std::span<TrackList> lists, const Clusters& clusters, const CommGraph& graph,
           const FusionConfig& config, FusionDiagnostics& diagnostics) {
    run(lists, clusters, 0, clusters.size(), graph, config, diagnostics);
  }
  /// The same for clusters [first, last) only. Clusters share no track, so two objects may run
  /// disjoint ranges of one step's clusters at once, each counting into its own diagnostics.
  void run(std::span<TrackList> lists, const Clusters& clusters, int first, int last,
           const CommGraph& graph, const FusionConfig& config, FusionDiagnostics& diagnostics);

 private:
  using Mat = Eigen::Matrix<double, N, N>;
  using Vec = Eigen::Matrix<double, N, 1>;
  using Info = Eigen::Matrix<double, N, N + 1>;        // [Ω | q]
  using Hybrid = Eigen::Matrix<double, N, 2 * N + 2>;  // [Ω⁻ | q⁻ | δΩ | δq]

  void runCi(std::span<TrackList> lists, std::span<const ClusterMember> members,
             const CommGraph& graph, int rounds, FusionDiagnostics& diagnostics);
  void runHcmci(std::span<TrackList> lists, std::span<const ClusterMember> members,
                const CommGraph& graph, int rounds, FusionDiagnostics& diagnostics);
  void runObserverAverage(std::span<TrackList> lists, std::span<const ClusterMember> members,
                          const CommGraph& graph, FusionDiagnostics& diagnostics);
  /// The links between usable members of the cluster, and each member's own weight before losses.
  void linkHolders(std::span<const ClusterMember> members, const CommGraph& graph);
  /// L rounds of the mixing above over the usable members; the result is left in `current`.
  template <typename Block>
  void mix(std::span<const ClusterMember> members, const CommGraph& graph, int rounds,
           std::vector<Block>& current, std::vector<Block>& next);
  /// mix() in closed form for a cluster of c usable members on a complete graph without losses
  /// (CI from kClosedFormFrom members on): every weight between holders is π = 1/n (n agents),
  /// so L rounds apply W^L with W = β I + π 11ᵀ over the holders, β = 1 − cπ; 1 is W's eigenvector
  /// of eigenvalue 1 and every vector orthogonal to it one of eigenvalue β, so
  ///   W^L y_k = ȳ + β^L (y_k − ȳ),
  /// ȳ the holders' mean: O(c) instead of O(c² L). The same values as the rounds up to rounding
  /// (tests/agents/fusion); clusters below kClosedFormFrom keep the rounds and their bits.
  template <typename Block>
  void mixOnCompleteGraph(const CommGraph& graph, int rounds, std::vector<Block>& current) const;
  static bool closedFormApplies(std::span<const ClusterMember> members, const CommGraph& graph);

  /// Size of the holder subgraph (usable members linked through usable members) of each member.
  void holderComponents(std::span<const ClusterMember> members);
  /// Marks a member unusable (no information pair): it neither sends nor receives.
  void exclude(std::span<const ClusterMember> members, int k);

  struct HolderLink {
    int sender = 0;       // member index of the neighbour j
    int link = 0;         // graph link id of j → i
    double weight = 0.0;  // π_ij
  };

  std::vector<HolderLink> holder_links_;  // CSR: member k's are [start[k], start[k + 1])
  std::vector<int> holder_link_start_;
  std::vector<double> own_weight_;  // per member: π_ii + Σ π_ij over neighbours without the track
  std::vector<int> slot_of_;        // per agent: its member index in the current cluster, or −1
  std::vector<char> usable_;        // per member
  std::vector<char> observed_;      // per member (observer average)
  std::vector<int> holders_;        // per member: ω
  std::vector<int> stack_;
  std::vector<Info> info_, info_next_;
  std::vector<Hybrid> hybrid_, hybrid_next_;
  std::vector<Eigen::Matrix<double, 1, 1>> existence_, existence_next_;            // CI: log-odds
  std::vector<Eigen::Matrix<double, 1, 2>> existence_pair_, existence_pair_next_;  // HCMCI
};

}  // namespace canopy::agents::fusion
