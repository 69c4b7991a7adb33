// Rule 2 of the association taken by key (TrackAssociation::linkByKey): the remembered links of
// the whole step at once, for teams where every pair of neighbours would otherwise walk every key
// they share. Same links, clusters and counters as pair by pair (track_association.cpp).
#include <algorithm>
#include <bit>

#include "agents/fusion/association_gate.h"
#include "agents/fusion/track_association.h"

namespace canopy::agents::fusion {
namespace {

// Two ints as one unsigned word that orders as the pair (hi, lo) does (the sign bits flipped).
std::uint64_t packed(int hi, int lo) {
  const auto flip = [](int v) { return static_cast<std::uint32_t>(v) ^ 0x80000000u; };
  return (std::uint64_t{flip(hi)} << 32) | flip(lo);
}

}  // namespace

template <int N>
void TrackAssociation<N>::linkByKey(double gate, FusionDiagnostics& diagnostics) {
  const std::size_t words = static_cast<std::size_t>(mask_words_);
  // The nodes of one key and label are one target's copies, at most one per agent: grouped by
  // a hash of (key, label), each group's nodes in ascending order (the groups' order is free:
  // their links and unions are independent).
  group_of_.clear();
  group_start_.assign(1, 0);
  node_group_.resize(nodes_.size());
  for (std::size_t n = 0; n < nodes_.size(); ++n) {
    const Node& node = nodes_[n];
    const KeyLabel key{packed(node.key.origin, node.key.serial), node.label};
    const auto [at, fresh] = group_of_.try_emplace(key, static_cast<int>(group_start_.size() - 1));
    if (fresh) group_start_.push_back(0);
    node_group_[n] = at->second;
    ++group_start_[at->second + 1];
  }
  for (std::size_t g = 1; g < group_start_.size(); ++g) group_start_[g] += group_start_[g - 1];
  group_nodes_.resize(nodes_.size());
  fill_.assign(group_start_.begin(), group_start_.end() - 1);
  for (std::size_t n = 0; n < nodes_.size(); ++n) {
    group_nodes_[fill_[node_group_[n]]++] = static_cast<int>(n);
  }
  partners_.assign(nodes_.size() * words, 0);
  copy_of_agent_.assign(static_cast<std::size_t>(agents_), -1);
  remembered_links_ = 0;
  for (std::size_t g = 0; g + 1 < group_start_.size(); ++g) {
    const int begin = group_start_[g], end = group_start_[g + 1];
    if (end - begin < 2) continue;
    linkKey(std::span<const int>(group_nodes_).subspan(begin, end - begin), gate);
  }
  diagnostics.remembered_matches += remembered_links_;

  // Per agent, the nodes without a partner at some neighbour (partners ⊂ neighbours): the only
  // ones a link can gate.
  unmatched_start_.assign(static_cast<std::size_t>(agents_) + 1, 0);
  unmatched_.clear();
  for (int a = 0; a < agents_; ++a) {
    const std::uint64_t* neighbours = &neighbours_[a * words];
    for (int n = node_start_[a]; n < node_start_[a + 1]; ++n) {
      if (!std::equal(neighbours, neighbours + words, &partners_[n * words])) {
        unmatched_.push_back(n);
      }
    }
    unmatched_start_[a + 1] = static_cast<int>(unmatched_.size());
  }
}

template <int N>
void TrackAssociation<N>::linkKey(std::span<const int> copies, double gate) {
  const std::size_t words = static_cast<std::size_t>(mask_words_);
  Vec2 centre = Vec2::Zero();
  for (const int n : copies) centre += nodes_[n].p;
  centre /= static_cast<double>(copies.size());
  core_.assign(words, 0);
  outside_.clear();
  for (const int n : copies) {
    const Node& copy = nodes_[n];
    copy_of_agent_[copy.agent] = n;
    if (inGateCore((copy.p - centre).norm(), eigenFloor(copy.S), gate)) {
      core_[copy.agent / 64] |= bitOf(copy.agent);
    } else {
      outside_.push_back(n);
    }
  }
  // Two core copies of neighbours pass the gate (association_gate.h): each core copy is
  // remembered with every neighbour in the core, each link seen from both ends.
  long ends = 0;
  for (const int n : copies) {
    const int a = nodes_[n].agent;
    if (!holds(core_.data(), a)) continue;
    for (std::size_t w = 0; w < words; ++w) {
      const std::uint64_t linked = neighbours_[a * words + w] & core_[w];
      partners_[n * words + w] |= linked;
      ends += std::popcount(linked);
    }
  }
  remembered_links_ += ends / 2;
  // A pair with a copy outside the core is gated as pair by pair (each such pair once).
  for (const int o : outside_) {
    const Node& x = nodes_[o];
    for (const int n : copies) {
      const Node& y = nodes_[n];
      const bool y_outside = !holds(core_.data(), y.agent);
      if (n == o || (y_outside && n < o)) continue;
      if (!holds(&neighbours_[x.agent * words], y.agent)) continue;
      if (!(mahalanobis2(x.p, x.S, y.p, y.S) <= gate)) continue;
      partners_[o * words + y.agent / 64] |= bitOf(y.agent);
      partners_[n * words + x.agent / 64] |= bitOf(x.agent);
      ++remembered_links_;
      unite(o, n);  // never refused: the copies of one key hold each agent once
    }
  }
  // The core's links join its copies per connected part of the graph among its agents.
  for (std::size_t w = 0; w < words; ++w) {
    while (core_[w] != 0) {
      const int start = static_cast<int>(w * 64) + std::countr_zero(core_[w]);
      joinPart(start, core_);
    }
  }
  for (const int n : copies) copy_of_agent_[nodes_[n].agent] = -1;
}

template <int N>
void TrackAssociation<N>::joinPart(int start_agent, std::span<std::uint64_t> remaining) {
  const std::size_t words = static_cast<std::size_t>(mask_words_);
  remaining[start_agent / 64] &= ~bitOf(start_agent);
  stack_.assign(1, start_agent);
  while (!stack_.empty()) {
    const int a = stack_.back();
    stack_.pop_back();
    for (std::size_t w = 0; w < words; ++w) {
      std::uint64_t reached = neighbours_[a * words + w] & remaining[w];
      remaining[w] &= ~reached;
      while (reached != 0) {
        const int b = static_cast<int>(w * 64) + std::countr_zero(reached);
        reached &= reached - 1;
        unite(copy_of_agent_[a], copy_of_agent_[b]);
        stack_.push_back(b);
      }
    }
  }
}

template <int N>
void TrackAssociation<N>::linkUnmatched(int i, int j, double gate) {
  const std::size_t words = static_cast<std::size_t>(mask_words_);
  rows_.clear();
  cols_.clear();
  for (int k = unmatched_start_[i]; k < unmatched_start_[i + 1]; ++k) {
    const int n = unmatched_[k];
    if (!holds(&partners_[n * words], j)) rows_.push_back(n);
  }
  for (int k = unmatched_start_[j]; k < unmatched_start_[j + 1]; ++k) {
    const int n = unmatched_[k];
    if (!holds(&partners_[n * words], i)) cols_.push_back(n);
  }
  gateAndAssign(gate);
}

template void TrackAssociation<3>::linkByKey(double, FusionDiagnostics&);
template void TrackAssociation<4>::linkByKey(double, FusionDiagnostics&);
template void TrackAssociation<3>::linkUnmatched(int, int, double);
template void TrackAssociation<4>::linkUnmatched(int, int, double);

}  // namespace canopy::agents::fusion
