#include "agents/fusion/comm_graph.h"

#include <algorithm>

namespace canopy::agents::fusion {

void CommGraph::build(std::span<const Vec2> positions, double range) {
  const int n = static_cast<int>(positions.size());
  const double range_squared = range * range;  // ∞ stays ∞
  first_.assign(static_cast<std::size_t>(n) + 1, 0);
  neighbour_.clear();
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      if (j != i && (positions[i] - positions[j]).squaredNorm() <= range_squared) {
        neighbour_.push_back(j);
      }
    }
    first_[i + 1] = static_cast<int>(neighbour_.size());
  }

  weight_.resize(neighbour_.size());
  self_weight_.assign(static_cast<std::size_t>(n), 1.0);
  for (int i = 0; i < n; ++i) {
    for (int link = first_[i]; link < first_[i + 1]; ++link) {
      const int j = neighbour_[link];
      weight_[link] = 1.0 / (1.0 + std::max(degree(i), degree(j)));  // π_ij, Metropolis
      self_weight_[i] -= weight_[link];                              // π_ii = 1 − Σ_j π_ij
    }
  }

  // Components by flooding from each unlabelled agent in index order.
  component_.assign(static_cast<std::size_t>(n), -1);
  component_count_ = 0;
  std::vector<int>& stack = stack_;
  for (int seed = 0; seed < n; ++seed) {
    if (component_[seed] >= 0) continue;
    stack.assign(1, seed);
    component_[seed] = component_count_;
    while (!stack.empty()) {
      const int i = stack.back();
      stack.pop_back();
      for (const int j : neighbours(i)) {
        if (component_[j] < 0) {
          component_[j] = component_count_;
          stack.push_back(j);
        }
      }
    }
    ++component_count_;
  }

  lost_.clear();
  lost_rounds_ = 0;
  messages_ = 0;
  lost_messages_ = 0;
}

void CommGraph::drawLosses(int rounds, double probability, std::span<RandomStream> streams) {
  const int links = static_cast<int>(neighbour_.size());
  messages_ = static_cast<long>(std::max(rounds, 0)) * links;
  lost_messages_ = 0;
  lost_rounds_ = 0;
  lost_.clear();
  if (probability <= 0.0 || rounds <= 0) return;
  lost_rounds_ = rounds;
  lost_.assign(static_cast<std::size_t>(rounds) * links, 0);
  for (int round = 0; round < rounds; ++round) {
    for (int i = 0; i < agents(); ++i) {
      for (int link = first_[i]; link < first_[i + 1]; ++link) {
        const bool lost = streams[i].bernoulli(probability);
        lost_[static_cast<std::size_t>(round) * links + link] = lost ? 1 : 0;
        lost_messages_ += lost ? 1 : 0;
      }
    }
  }
}

bool CommGraph::linked(int i, int j) const {
  const std::span<const int> list = neighbours(i);
  return std::binary_search(list.begin(), list.end(), j);
}

}  // namespace canopy::agents::fusion
