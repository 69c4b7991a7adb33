#include "agents/fusion/information_consensus.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>

#include "agents/fusion/small_cholesky.h"

namespace canopy::agents::fusion {
namespace {

/// Information pair of a Gaussian: Ω = P⁻¹ and q = P⁻¹x, by Cholesky solves (no explicit
/// inverse). False when P is not positive definite or not finite.
template <int N>
bool toInformation(const Gaussian<N>& g, Eigen::Ref<Eigen::Matrix<double, N, N>> omega,
                   Eigen::Ref<Eigen::Matrix<double, N, 1>> q) {
  if (!g.x.allFinite()) return false;
  const SmallCholesky<N> cholesky(g.P);
  if (!cholesky.ok()) return false;
  omega = cholesky.inverse();  // Ω = P⁻¹ (N×N)
  q = cholesky.solve(g.x);     // q = P⁻¹ x (N)
  return true;
}

/// The Gaussian of an information pair: P = Ω⁻¹, x = Ω⁻¹q. False when Ω is not positive
/// definite (then g is left as it was).
template <int N>
bool fromInformation(const Eigen::Matrix<double, N, N>& omega, const Eigen::Matrix<double, N, 1>& q,
                     Gaussian<N>& g) {
  if (!q.allFinite()) return false;
  const SmallCholesky<N> cholesky(0.5 * (omega + omega.transpose()));
  if (!cholesky.ok()) return false;
  g.P = cholesky.inverse();  // P = Ω⁻¹ (N×N)
  g.x = cholesky.solve(q);   // x = Ω⁻¹ q (N)
  return true;
}

/// Whether two fixed-size matrices hold the same bits (equal values could differ in a zero's sign
/// or a NaN's payload, and so in what is computed from them).
template <typename Matrix>
bool sameBits(const Matrix& a, const Matrix& b) {
  return std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<std::size_t>(a.size())) == 0;
}

template <int N>
bool sameBits(const Gaussian<N>& a, const Gaussian<N>& b) {
  return sameBits(a.x, b.x) && sameBits(a.P, b.P);
}

// Existence crosses as log-odds, ln(r / (1 − r)), kept within ±ln(10⁹ − 1) so that r = 0 or 1
// stays finite.
constexpr double kExistenceFloor = 1e-9;
double logOdds(double r) {
  const double p = std::clamp(r, kExistenceFloor, 1.0 - kExistenceFloor);
  return std::log(p / (1.0 - p));
}
double fromLogOdds(double l) {
  return 1.0 / (1.0 + std::exp(-l));
}  // r = 1 / (1 + e^{−l})

}  // namespace

template <int N>
void InformationConsensus<N>::run(std::span<TrackList> lists, const Clusters& clusters, int first,
                                  int last, const CommGraph& graph, const FusionConfig& config,
                                  FusionDiagnostics& diagnostics) {
  slot_of_.assign(static_cast<std::size_t>(graph.agents()), -1);
  const int rounds = config.rounds > 0 ? config.rounds : 0;
  for (int c = first; c < last; ++c) {
    const std::span<const ClusterMember> members = clusters.of(c);
    if (members.size() < 2) continue;  // nothing to fuse with
    usable_.assign(members.size(), 1);
    for (std::size_t k = 0; k < members.size(); ++k) {
      slot_of_[members[k].agent] = static_cast<int>(k);
    }
    switch (config.method) {
      case FusionMethod::ci:
        runCi(lists, members, graph, rounds, diagnostics);
        break;
      case FusionMethod::hcmci:
        runHcmci(lists, members, graph, rounds, diagnostics);
        break;
      case FusionMethod::observer_average:
        runObserverAverage(lists, members, graph, diagnostics);
        break;
    }
    for (const ClusterMember& member : members) slot_of_[member.agent] = -1;
  }
}

template <int N>
void InformationConsensus<N>::exclude(std::span<const ClusterMember> members, int k) {
  usable_[k] = 0;
  slot_of_[members[k].agent] = -1;
}

template <int N>
void InformationConsensus<N>::linkHolders(std::span<const ClusterMember> members,
                                          const CommGraph& graph) {
  const int count = static_cast<int>(members.size());
  holder_links_.clear();
  holder_link_start_.resize(members.size() + 1);
  own_weight_.resize(members.size());
  for (int k = 0; k < count; ++k) {
    holder_link_start_[k] = static_cast<int>(holder_links_.size());
    const int i = members[k].agent;
    own_weight_[k] = graph.selfWeight(i);  // π_ii ...
    if (!usable_[k]) continue;
    const std::span<const int> neighbours = graph.neighbours(i);
    const std::span<const double> weights = graph.weights(i);
    for (std::size_t e = 0; e < neighbours.size(); ++e) {
      const int s = slot_of_[neighbours[e]];
      if (s >= 0) {
        holder_links_.push_back({s, graph.firstLink(i) + static_cast<int>(e), weights[e]});
      } else {
        own_weight_[k] += weights[e];  // ... plus π_ij of every neighbour without the track
      }
    }
  }
  holder_link_start_[count] = static_cast<int>(holder_links_.size());
}

template <int N>
template <typename Block>
void InformationConsensus<N>::mix(std::span<const ClusterMember> members, const CommGraph& graph,
                                  int rounds, std::vector<Block>& current,
                                  std::vector<Block>& next) {
  const int count = static_cast<int>(members.size());
  next.resize(current.size());
  for (int round = 0; round < rounds; ++round) {
    for (int k = 0; k < count; ++k) {
      if (!usable_[k]) {
        next[k] = current[k];
        continue;
      }
      double own_weight = own_weight_[k];
      Block sum = Block::Zero();
      for (int l = holder_link_start_[k]; l < holder_link_start_[k + 1]; ++l) {
        const HolderLink& link = holder_links_[l];
        if (graph.delivered(round, link.link)) {
          sum.noalias() += link.weight * current[link.sender];  // Σ_j π_ij y_j
        } else {
          own_weight += link.weight;  // a lost message's weight stays with the receiver
        }
      }
      sum.noalias() += own_weight * current[k];
      next[k] = sum;
    }
    std::swap(current, next);
  }
}

template <int N>
bool InformationConsensus<N>::closedFormApplies(std::span<const ClusterMember> members,
                                                const CommGraph& graph) {
  return members.size() >= kClosedFormFrom && graph.complete() && graph.lossless();
}

template <int N>
template <typename Block>
void InformationConsensus<N>::mixOnCompleteGraph(const CommGraph& graph, int rounds,
                                                 std::vector<Block>& current) const {
  const int count = static_cast<int>(current.size());
  int holders = 0;  // c: the usable members
  Block sum = Block::Zero();
  for (int k = 0; k < count; ++k) {
    if (!usable_[k]) continue;
    sum += current[k];
    ++holders;
  }
  if (holders < 2) return;                                   // nothing heard: every value stays
  const double pi = 1.0 / graph.agents();                    // π_ij = 1 / (1 + (n − 1))
  const double beta = std::pow(1.0 - holders * pi, rounds);  // β^L
  const Block mean = sum / holders;                          // ȳ
  for (int k = 0; k < count; ++k) {
    if (usable_[k]) current[k] = mean + beta * (current[k] - mean);  // ȳ + β^L (y_k − ȳ)
  }
}

template <int N>
void InformationConsensus<N>::runCi(std::span<TrackList> lists,
                                    std::span<const ClusterMember> members, const CommGraph& graph,
                                    int rounds, FusionDiagnostics& diagnostics) {
  const int count = static_cast<int>(members.size());
  // Copies that no agent updated since the last fusion hold the same bits (each predicted from
  // the one fused value): in a large cluster a member equal to the last one converted takes its
  // result, in and out, instead of another Cholesky (the same bits, the same failures counted).
  const bool reuse = members.size() >= kReuseFrom;
  auto posteriorOf = [&](int k) -> Gaussian<N>& {
    return lists[members[k].agent][members[k].track].posterior;
  };
  info_.resize(members.size());
  int last = -1;  // the last member converted
  for (int k = 0; k < count; ++k) {
    const Gaussian<N>& posterior = posteriorOf(k);
    if (reuse && last >= 0 && sameBits(posterior, posteriorOf(last))) {
      if (usable_[last]) {
        info_[k] = info_[last];
      } else {
        exclude(members, k);
        ++diagnostics.numerical_failures;
      }
      continue;
    }
    last = k;
    if (!toInformation<N>(posterior, info_[k].template leftCols<N>(), info_[k].col(N))) {
      exclude(members, k);
      ++diagnostics.numerical_failures;
    }
  }
  existence_.resize(members.size());
  for (int k = 0; k < count; ++k) {
    existence_[k](0) = logOdds(lists[members[k].agent][members[k].track].existence);
  }
  // Ω_i ← Σ_j π_ij Ω_j, q_i ← Σ_j π_ij q_j, L rounds (Battistelli & Chisci 2014). Existence: the
  // same rounds on the log-odds l = ln(r / (1 − r)), i.e. the normalised geometric mean of the
  // Bernoulli distributions, as CI's information average is the Gaussians' geometric mean
  // (docs/design-notes.md).
  if (closedFormApplies(members, graph)) {
    mixOnCompleteGraph(graph, rounds, info_);
    mixOnCompleteGraph(graph, rounds, existence_);
  } else {
    linkHolders(members, graph);
    mix(members, graph, rounds, info_, info_next_);
    mix(members, graph, rounds, existence_, existence_next_);
  }
  last = -1;
  bool last_converted = false;
  for (int k = 0; k < count; ++k) {
    if (!usable_[k]) continue;
    tracking::Track<N>& track = lists[members[k].agent][members[k].track];
    track.existence = fromLogOdds(existence_[k](0));
    Gaussian<N>& posterior = track.posterior;
    if (reuse && last >= 0 && sameBits(info_[k], info_[last])) {
      if (last_converted) {
        posterior = posteriorOf(last);
      } else {
        ++diagnostics.numerical_failures;  // left as it was, as the last one
      }
      continue;
    }
    last = k;
    const Mat omega = info_[k].template leftCols<N>();
    const Vec q = info_[k].col(N);
    last_converted = fromInformation<N>(omega, q, posterior);
    if (!last_converted) ++diagnostics.numerical_failures;
  }
}

template <int N>
void InformationConsensus<N>::runHcmci(std::span<TrackList> lists,
                                       std::span<const ClusterMember> members,
                                       const CommGraph& graph, int rounds,
                                       FusionDiagnostics& diagnostics) {
  const int count = static_cast<int>(members.size());
  hybrid_.resize(members.size());
  existence_pair_.resize(members.size());
  for (int k = 0; k < count; ++k) {
    const tracking::Track<N>& track = lists[members[k].agent][members[k].track];
    Hybrid& y = hybrid_[k];
    Mat omega_post;
    Vec q_post;
    const bool ok = toInformation<N>(track.prior, y.template leftCols<N>(), y.col(N)) &&
                    toInformation<N>(track.posterior, omega_post, q_post);
    if (!ok) {
      exclude(members, k);
      ++diagnostics.numerical_failures;
      continue;
    }
    // Existence: the predicted log-odds and the scan's evidence, l − l⁻ (zero when adopted).
    existence_pair_[k](0) = logOdds(track.existence_prior);
    existence_pair_[k](1) =
        members[k].adopted ? 0.0 : logOdds(track.existence) - existence_pair_[k](0);
    if (members[k].adopted) {
      y.template rightCols<N + 1>().setZero();  // an adopted copy brings no measurement
    } else {
      y.template block<N, N>(0, N + 1) = omega_post - y.template leftCols<N>();  // δΩ = Ω − Ω⁻
      y.col(2 * N + 1) = q_post - y.col(N);                                      // δq = q − q⁻
    }
  }
  linkHolders(members, graph);
  holderComponents(members);
  // Consensus on prior information and on novel information, L rounds each (Battistelli,
  // Chisci, Mugnai, Farina & Graziano 2015).
  mix(members, graph, rounds, hybrid_, hybrid_next_);
  mix(members, graph, rounds, existence_pair_, existence_pair_next_);
  for (int k = 0; k < count; ++k) {
    if (!usable_[k]) continue;
    const Hybrid& y = hybrid_[k];
    const double omega_scale = holders_[k];  // ω
    // Existence as independent evidence: l = l⁻ + ω (l − l⁻), the agents' log likelihood ratios
    // summed (their mean times the holders), as HCMCI sums the novel information.
    lists[members[k].agent][members[k].track].existence =
        fromLogOdds(existence_pair_[k](0) + omega_scale * existence_pair_[k](1));
    // Ω = Ω⁻ + ω δΩ, q = q⁻ + ω δq (Battistelli, Chisci, Mugnai, Farina & Graziano 2015).
    const Mat omega = y.template leftCols<N>() + omega_scale * y.template block<N, N>(0, N + 1);
    const Vec q = y.col(N) + omega_scale * y.col(2 * N + 1);
    Gaussian<N>& posterior = lists[members[k].agent][members[k].track].posterior;
    if (!fromInformation<N>(omega, q, posterior)) ++diagnostics.numerical_failures;
  }
}

template <int N>
void InformationConsensus<N>::runObserverAverage(std::span<TrackList> lists,
                                                 std::span<const ClusterMember> members,
                                                 const CommGraph& graph,
                                                 FusionDiagnostics& diagnostics) {
  const int count = static_cast<int>(members.size());
  info_.resize(members.size());
  observed_.assign(members.size(), 0);
  for (int k = 0; k < count; ++k) {
    const tracking::Track<N>& track = lists[members[k].agent][members[k].track];
    observed_[k] = track.detected && !members[k].adopted ? 1 : 0;
    if (!toInformation<N>(track.posterior, info_[k].template leftCols<N>(), info_[k].col(N))) {
      exclude(members, k);
      ++diagnostics.numerical_failures;
    }
  }
  for (int k = 0; k < count; ++k) {
    if (!usable_[k]) continue;
    const int i = members[k].agent;
    Info sum = Info::Zero();
    double existence_sum = 0.0;  // Σ of the observers' log-odds
    int observers = 0;
    if (observed_[k]) {
      sum += info_[k];
      existence_sum += logOdds(lists[i][members[k].track].existence);
      ++observers;
    }
    const std::span<const int> neighbours = graph.neighbours(i);
    for (std::size_t e = 0; e < neighbours.size(); ++e) {
      const int s = slot_of_[neighbours[e]];
      if (s < 0 || !observed_[s] || !graph.delivered(0, graph.firstLink(i) + static_cast<int>(e))) {
        continue;
      }
      sum += info_[s];
      existence_sum += logOdds(lists[members[s].agent][members[s].track].existence);
      ++observers;
    }
    if (observers == 0) continue;  // nobody heard saw it: keep the local posterior
    // (Ω, q) = mean over the observers heard (the reference simulator's rule); existence: the
    // mean of their log-odds.
    sum /= static_cast<double>(observers);
    lists[i][members[k].track].existence = fromLogOdds(existence_sum / observers);
    const Mat omega = sum.template leftCols<N>();
    const Vec q = sum.col(N);
    Gaussian<N>& posterior = lists[i][members[k].track].posterior;
    if (!fromInformation<N>(omega, q, posterior)) ++diagnostics.numerical_failures;
  }
}

template <int N>
void InformationConsensus<N>::holderComponents(std::span<const ClusterMember> members) {
  const int count = static_cast<int>(members.size());
  holders_.assign(members.size(), 0);
  for (int seed = 0; seed < count; ++seed) {
    if (!usable_[seed] || holders_[seed] != 0) continue;
    // Flood the usable members reachable from `seed` (marked −1), then write the count.
    stack_.assign(1, seed);
    holders_[seed] = -1;
    for (std::size_t top = 0; top < stack_.size(); ++top) {
      const int k = stack_[top];
      for (int l = holder_link_start_[k]; l < holder_link_start_[k + 1]; ++l) {
        const int s = holder_links_[l].sender;
        if (holders_[s] == 0) {
          holders_[s] = -1;
          stack_.push_back(s);
        }
      }
    }
    for (const int k : stack_) holders_[k] = static_cast<int>(stack_.size());
  }
}

template class InformationConsensus<3>;
template class InformationConsensus<4>;

}  // namespace canopy::agents::fusion
