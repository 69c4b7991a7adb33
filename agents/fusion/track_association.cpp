#include "agents/fusion/track_association.h"

#include <algorithm>
#include <bit>
#include <limits>
#include <tuple>

#include "agents/fusion/association_gate.h"

namespace canopy::agents::fusion {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace

template <int N>
void TrackAssociation<N>::associate(std::span<TrackList> lists, const CommGraph& graph, double gate,
                                    KeyMint& mint, Clusters& clusters,
                                    FusionDiagnostics& diagnostics, TaskPool* pool) {
  agents_ = graph.agents();
  mask_words_ = (agents_ + 63) / 64;
  gatherNodes(lists, pool);
  startUnionFind();
  remembered_.clear();
  assigned_.clear();
  gatherNeighbourSets(graph);
  const bool by_key = agents_ >= grouped_from_ && keysUniquePerAgent();
  if (by_key) linkByKey(gate, diagnostics);
  for (int i = 0; i < agents_; ++i) {
    for (const int j : graph.neighbours(i)) {
      if (j <= i) continue;
      if (by_key) {
        linkUnmatched(i, j, gate);
      } else {
        linkNeighbours(i, j, gate);
      }
    }
  }
  cluster(diagnostics);
  chooseKeys(graph, mint, diagnostics);
  planAdoptions();
  writeOut(lists, clusters, diagnostics);
}

template <int N>
void TrackAssociation<N>::gatherNodes(std::span<const TrackList> lists, TaskPool* pool) {
  node_start_.assign(static_cast<std::size_t>(agents_) + 1, 0);
  for (int a = 0; a < agents_; ++a) {
    const int count = static_cast<int>(lists[a].size());
    node_start_[a + 1] = node_start_[a] + count;
  }
  nodes_.resize(static_cast<std::size_t>(node_start_[agents_]));
  by_key_.resize(nodes_.size());
  // Agent a writes only its own rows [node_start_[a], node_start_[a + 1]).
  forEachTask(pool, static_cast<std::size_t>(agents_), [&](std::size_t agent) {
    const int a = static_cast<int>(agent);
    for (int n = node_start_[a]; n < node_start_[a + 1]; ++n) {
      const tracking::Track<N>& track = lists[a][n - node_start_[a]];
      Node& node = nodes_[n];
      node.key = track.key;
      node.label = track.label;
      node.agent = a;
      node.track = n - node_start_[a];
      node.confirmed = track.status == tracking::TrackStatus::confirmed;
      node.p = track.posterior.x.template head<2>();
      node.S = track.posterior.P.template topLeftCorner<2, 2>();
      by_key_[n] = n;
    }
    std::sort(
        by_key_.begin() + node_start_[a], by_key_.begin() + node_start_[a + 1],
        [this](int x, int y) { return std::tie(nodes_[x].key, x) < std::tie(nodes_[y].key, y); });
  });
  taken_.assign(nodes_.size(), 0);
  link_stamp_ = 0;
}

template <int N>
void TrackAssociation<N>::gatherNeighbourSets(const CommGraph& graph) {
  neighbours_.assign(static_cast<std::size_t>(agents_) * mask_words_, 0);
  for (int a = 0; a < agents_; ++a) {
    for (const int b : graph.neighbours(a)) {
      neighbours_[static_cast<std::size_t>(a) * mask_words_ + b / 64] |= bitOf(b);
    }
  }
}

template <int N>
bool TrackAssociation<N>::keysUniquePerAgent() const {
  for (int a = 0; a < agents_; ++a) {
    for (int k = node_start_[a] + 1; k < node_start_[a + 1]; ++k) {
      if (nodes_[by_key_[k - 1]].key == nodes_[by_key_[k]].key) return false;
    }
  }
  return true;
}

template <int N>
void TrackAssociation<N>::linkNeighbours(int i, int j, double gate) {
  ++link_stamp_;
  // Memory: tracks that already share a key stay matched while they stay within the gate.
  int ia = node_start_[i];
  int ib = node_start_[j];
  while (ia < node_start_[i + 1] && ib < node_start_[j + 1]) {
    const Node& x = nodes_[by_key_[ia]];
    const Node& y = nodes_[by_key_[ib]];
    if (x.key < y.key) {
      ++ia;
    } else if (y.key < x.key) {
      ++ib;
    } else {
      if (x.label == y.label) {
        const double d2 = mahalanobis2(x.p, x.S, y.p, y.S);
        if (d2 <= gate) {
          remembered_.push_back({d2, by_key_[ia], by_key_[ib]});
          taken_[by_key_[ia]] = link_stamp_;
          taken_[by_key_[ib]] = link_stamp_;
        }
      }
      ++ia;
      ++ib;
    }
  }

  rows_.clear();
  cols_.clear();
  for (int n = node_start_[i]; n < node_start_[i + 1]; ++n) {
    if (taken_[n] != link_stamp_) rows_.push_back(n);
  }
  for (int n = node_start_[j]; n < node_start_[j + 1]; ++n) {
    if (taken_[n] != link_stamp_) cols_.push_back(n);
  }
  gateAndAssign(gate);
}

template <int N>
void TrackAssociation<N>::gateAndAssign(double gate) {
  // The rest (rows_ of i, cols_ of j): every same-label pair within the gate is a candidate for
  // the assignment.
  gated_.clear();
  for (int r = 0; r < static_cast<int>(rows_.size()); ++r) {
    const Node& x = nodes_[rows_[r]];
    for (int c = 0; c < static_cast<int>(cols_.size()); ++c) {
      const Node& y = nodes_[cols_[c]];
      if (x.label != y.label) continue;  // association never mixes labels
      const double d2 = mahalanobis2(x.p, x.S, y.p, y.S);
      if (d2 <= gate) gated_.push_back({r, c, d2});
    }
  }
  if (!gated_.empty()) assignComponents(gate);
}

template <int N>
void TrackAssociation<N>::assignComponents(double gate) {
  // Connected components of the gating graph are independent assignment problems; solving
  // them apart keeps each Hungarian problem as small as the targets' crowding allows.
  const int rows = static_cast<int>(rows_.size());
  const int cols = static_cast<int>(cols_.size());
  local_parent_.resize(static_cast<std::size_t>(rows + cols));
  for (int k = 0; k < rows + cols; ++k) local_parent_[k] = k;
  auto root = [this](int k) {
    while (local_parent_[k] != k) k = local_parent_[k] = local_parent_[local_parent_[k]];
    return k;
  };
  for (const Gated& g : gated_) {
    const int a = root(g.row);
    const int b = root(rows + g.col);
    if (a != b) local_parent_[std::max(a, b)] = std::min(a, b);
  }
  std::sort(gated_.begin(), gated_.end(), [&](const Gated& x, const Gated& y) {
    return std::make_tuple(root(x.row), x.row, x.col) < std::make_tuple(root(y.row), y.row, y.col);
  });
  row_slot_.assign(static_cast<std::size_t>(rows), -1);
  col_slot_.assign(static_cast<std::size_t>(cols), -1);
  for (std::size_t begin = 0; begin < gated_.size();) {
    const int component = root(gated_[begin].row);
    std::size_t end = begin;
    group_rows_.clear();
    group_cols_.clear();
    for (; end < gated_.size() && root(gated_[end].row) == component; ++end) {
      const Gated& g = gated_[end];
      if (row_slot_[g.row] < 0) {
        row_slot_[g.row] = static_cast<int>(group_rows_.size());
        group_rows_.push_back(g.row);
      }
      if (col_slot_[g.col] < 0) {
        col_slot_[g.col] = static_cast<int>(group_cols_.size());
        group_cols_.push_back(g.col);
      }
    }
    const int group_row_count = static_cast<int>(group_rows_.size());
    const int group_col_count = static_cast<int>(group_cols_.size());
    cost_.assign(static_cast<std::size_t>(group_row_count) * group_col_count, kInf);
    for (std::size_t k = begin; k < end; ++k) {
      const Gated& g = gated_[k];
      cost_[static_cast<std::size_t>(row_slot_[g.row]) * group_col_count + col_slot_[g.col]] =
          g.cost;
    }
    pairs_.clear();
    assignment_.solve(cost_, group_row_count, group_col_count, gate, pairs_);
    for (const AssignedPair& pair : pairs_) {
      assigned_.push_back({pair.cost, rows_[group_rows_[pair.row]], cols_[group_cols_[pair.col]]});
    }
    begin = end;
  }
}

template <int N>
int TrackAssociation<N>::find(int node) {
  while (parent_[node] != node) node = parent_[node] = parent_[parent_[node]];
  return node;
}

template <int N>
bool TrackAssociation<N>::unite(int a, int b) {
  const int ra = find(a);
  const int rb = find(b);
  if (ra == rb) return true;
  const std::size_t wa = static_cast<std::size_t>(ra) * mask_words_;
  const std::size_t wb = static_cast<std::size_t>(rb) * mask_words_;
  for (int w = 0; w < mask_words_; ++w) {
    if ((mask_[wa + w] & mask_[wb + w]) != 0) return false;  // an agent would hold two tracks
  }
  const int keep = std::min(ra, rb);
  const int drop = std::max(ra, rb);
  parent_[drop] = keep;
  const std::size_t wk = static_cast<std::size_t>(keep) * mask_words_;
  const std::size_t wd = static_cast<std::size_t>(drop) * mask_words_;
  for (int w = 0; w < mask_words_; ++w) mask_[wk + w] |= mask_[wd + w];
  return true;
}

template <int N>
void TrackAssociation<N>::startUnionFind() {
  const int count = static_cast<int>(nodes_.size());
  parent_.resize(nodes_.size());
  mask_.assign(nodes_.size() * mask_words_, 0);
  for (int n = 0; n < count; ++n) {
    parent_[n] = n;
    const int agent = nodes_[n].agent;
    mask_[static_cast<std::size_t>(n) * mask_words_ + agent / 64] = bitOf(agent);
  }
}

template <int N>
void TrackAssociation<N>::cluster(FusionDiagnostics& diagnostics) {
  const int count = static_cast<int>(nodes_.size());
  // Remembered links first (joined already when linked by key), then the assigned ones.
  for (const Link& link : remembered_) {
    if (unite(link.a, link.b)) {
      ++diagnostics.remembered_matches;
    } else {
      ++diagnostics.refused_matches;
    }
  }
  std::sort(assigned_.begin(), assigned_.end(), [](const Link& x, const Link& y) {
    return std::tie(x.cost, x.a, x.b) < std::tie(y.cost, y.a, y.b);
  });
  for (const Link& link : assigned_) {
    if (unite(link.a, link.b)) {
      ++diagnostics.new_matches;
    } else {
      ++diagnostics.refused_matches;
    }
  }

  // Number the clusters in the order of their first node; note key, size and confirmation.
  root_cluster_.assign(nodes_.size(), -1);
  cluster_of_.resize(nodes_.size());
  keys_.clear();
  first_node_.clear();
  size_.clear();
  confirmed_.clear();
  for (int n = 0; n < count; ++n) {
    const int root = find(n);
    if (root_cluster_[root] < 0) {
      root_cluster_[root] = static_cast<int>(keys_.size());
      keys_.push_back(nodes_[n].key);
      first_node_.push_back(n);
      size_.push_back(0);
      confirmed_.push_back(0);
    }
    const int c = root_cluster_[root];
    cluster_of_[n] = c;
    keys_[c] = std::min(keys_[c], nodes_[n].key);  // matched tracks adopt the smaller key
    ++size_[c];
    if (nodes_[n].confirmed) confirmed_[c] = 1;
  }
}

template <int N>
void TrackAssociation<N>::chooseKeys(const CommGraph& graph, KeyMint& mint,
                                     FusionDiagnostics& diagnostics) {
  const int clusters = static_cast<int>(keys_.size());
  order_.resize(static_cast<std::size_t>(clusters));
  for (int c = 0; c < clusters; ++c) order_[c] = c;
  auto rank = [&](int c) {
    return std::make_tuple(graph.component(nodes_[first_node_[c]].agent), keys_[c], -size_[c],
                           first_node_[c]);
  };
  std::sort(order_.begin(), order_.end(), [&](int x, int y) { return rank(x) < rank(y); });
  // Clusters that want the same key in one part of the network are now adjacent, the one that
  // keeps it first; the others get fresh keys.
  int kept_part = -1;
  TrackKey kept_key;
  for (const int c : order_) {
    const int part = graph.component(nodes_[first_node_[c]].agent);
    if (part == kept_part && keys_[c] == kept_key) {
      keys_[c] = mint.next(nodes_[first_node_[c]].agent);
      ++diagnostics.rekeys;
    } else {
      kept_part = part;
      kept_key = keys_[c];
    }
  }
}

template <int N>
void TrackAssociation<N>::planAdoptions() {
  adoptions_.clear();
  const int count = static_cast<int>(nodes_.size());
  for (int n = 0; n < count; ++n) {  // nodes ascend by agent: the lowest member offers first
    const int c = cluster_of_[n];
    if (!confirmed_[c]) continue;
    // The cluster's agent set (mask_ of its root): its members, and from here on the agents it
    // was offered to, so that an agent next to several members adopts the cluster once (the
    // nodes of one cluster are not adjacent: a "last cluster offered" per agent let a second
    // member offer it again, and the copies multiplied step after step).
    const std::size_t words = static_cast<std::size_t>(find(n)) * mask_words_;
    // Each neighbour not in the set yet adopts it, by increasing agent, a word at a time.
    const std::size_t own = static_cast<std::size_t>(nodes_[n].agent) * mask_words_;
    for (int w = 0; w < mask_words_; ++w) {
      std::uint64_t& word = mask_[words + w];
      std::uint64_t offered = neighbours_[own + w] & ~word;
      word |= neighbours_[own + w];
      for (; offered != 0; offered &= offered - 1) {
        adoptions_.push_back({c, w * 64 + std::countr_zero(offered), n});
      }
    }
  }
}

template <int N>
void TrackAssociation<N>::writeOut(std::span<TrackList> lists, Clusters& clusters,
                                   FusionDiagnostics& diagnostics) {
  const int cluster_count = static_cast<int>(keys_.size());
  clusters.keys.assign(keys_.begin(), keys_.end());
  clusters.start.assign(static_cast<std::size_t>(cluster_count) + 1, 0);
  for (std::size_t n = 0; n < nodes_.size(); ++n) ++clusters.start[cluster_of_[n] + 1];
  for (const Adoption& adoption : adoptions_) ++clusters.start[adoption.cluster + 1];
  for (int c = 0; c < cluster_count; ++c) clusters.start[c + 1] += clusters.start[c];
  clusters.members.resize(static_cast<std::size_t>(clusters.start[cluster_count]));
  order_.assign(clusters.start.begin(), clusters.start.end() - 1);  // fill position per cluster

  for (std::size_t n = 0; n < nodes_.size(); ++n) {
    const Node& node = nodes_[n];
    const int c = cluster_of_[n];
    lists[node.agent][node.track].key = keys_[c];
    clusters.members[order_[c]++] = {node.agent, node.track, false};
  }
  for (const Adoption& adoption : adoptions_) {
    const Node& source = nodes_[adoption.source];
    tracking::Track<N> copy = lists[source.agent][source.track];
    copy.key = keys_[adoption.cluster];
    copy.status = tracking::TrackStatus::confirmed;
    copy.expected_misses = 0;
    copy.detected = false;
    copy.merge_streak = 0;  // its partner was a track of the source's list
    copy.strongest_detection = -1;  // the source's scan, not this agent's
    TrackList& list = lists[adoption.agent];
    list.push_back(copy);
    clusters.members[order_[adoption.cluster]++] = {adoption.agent,
                                                    static_cast<int>(list.size()) - 1, true};
    ++diagnostics.adoptions;
  }
  if (adoptions_.empty()) return;
  for (int c = 0; c < cluster_count; ++c) {
    std::sort(clusters.members.begin() + clusters.start[c],
              clusters.members.begin() + clusters.start[c + 1],
              [](const ClusterMember& x, const ClusterMember& y) { return x.agent < y.agent; });
  }
}

template class TrackAssociation<3>;
template class TrackAssociation<4>;

}  // namespace canopy::agents::fusion
