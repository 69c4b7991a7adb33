#pragma once
// The team's communication graph at one step: who can hear whom, the Metropolis consensus
// weights, and which consensus messages are lost (comm_drop).
#include <cstdint>
#include <span>
#include <vector>

#include "core/random.h"
#include "core/types.h"

namespace canopy::agents::fusion {

/// Undirected links between UAVs within range of each other, stored as a sorted adjacency list.
/// Every directed link j → i has an id: the k-th neighbour of i is link firstLink(i) + k.
class CommGraph {
 public:
  /// Links every pair of UAVs whose ground positions (m) lie within `range` (m) of each other;
  /// range = ∞ gives the complete graph. Computes the Metropolis weights (Xiao, Boyd & Lall 2005)
  /// π_ij = 1 / (1 + max(deg_i, deg_j)), π_ii = 1 − Σ_j π_ij, and the connected components.
  /// Clears the losses drawn for the previous step (every message is delivered).
  void build(std::span<const Vec2> positions, double range);

  /// For each of `rounds` message exchanges and each directed link j → i, draws whether the
  /// message is lost, with `probability`, from receiver i's stream (streams[i]: one per agent).
  /// Draws happen in a fixed order (round, receiver, neighbour), so the losses depend only on
  /// the streams. probability ≤ 0 draws nothing and loses nothing.
  void drawLosses(int rounds, double probability, std::span<RandomStream> streams);

  int agents() const { return static_cast<int>(self_weight_.size()); }
  int degree(int i) const { return first_[i + 1] - first_[i]; }
  /// Neighbours of i, ascending, and the Metropolis weights π_ij in the same order.
  std::span<const int> neighbours(int i) const {
    return {neighbour_.data() + first_[i], sizeSpan(i)};
  }
  std::span<const double> weights(int i) const { return {weight_.data() + first_[i], sizeSpan(i)}; }
  double selfWeight(int i) const { return self_weight_[i]; }  // π_ii
  /// Id of the link from i's first neighbour to i.
  int firstLink(int i) const { return first_[i]; }
  bool linked(int i, int j) const;
  /// Every agent hears every other (as range = ∞ gives).
  bool complete() const {
    return neighbour_.size() == self_weight_.size() * (self_weight_.size() - 1);
  }
  /// Connected components, numbered 0, 1, ... in the order of their smallest member.
  int component(int i) const { return component_[i]; }
  int componentCount() const { return component_count_; }

  /// Whether the message on link `link` in exchange `round` arrived (true for every round
  /// beyond those drawn and for every link when no losses were drawn).
  bool delivered(int round, int link) const {
    return round >= lost_rounds_ ||
           lost_[static_cast<std::size_t>(round) * neighbour_.size() + link] == 0;
  }
  /// Whether no message of this step can be lost (no losses were drawn).
  bool lossless() const { return lost_rounds_ == 0; }
  long messages() const { return messages_; }           // directed messages of this step
  long lostMessages() const { return lost_messages_; }  // of which lost

 private:
  std::size_t sizeSpan(int i) const { return static_cast<std::size_t>(degree(i)); }

  std::vector<int> first_;           // CSR: links of i are [first_[i], first_[i + 1])
  std::vector<int> neighbour_;       // the sender j of each link j → i
  std::vector<double> weight_;       // π_ij of each link
  std::vector<double> self_weight_;  // π_ii
  std::vector<int> component_;
  std::vector<int> stack_;  // flood-fill scratch
  int component_count_ = 0;
  std::vector<char> lost_;  // round-major: lost_[round · links + link]
  int lost_rounds_ = 0;
  long messages_ = 0;
  long lost_messages_ = 0;
};

}  // namespace canopy::agents::fusion
