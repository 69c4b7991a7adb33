#include "metrics/ospa.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <unordered_map>

namespace canopy::metrics {
namespace {

// Up to this many pairs the whole problem is one Hungarian solve (cheaper than the grid).
constexpr long kWholeUpTo = 256;

// Union-find with path halving over the m + n points (small ones first).
int findRoot(std::vector<int>& parent, int a) {
  while (parent[a] != a) a = parent[a] = parent[parent[a]];
  return a;
}

std::uint64_t cellKey(std::int64_t cx, std::int64_t cy) {
  return (static_cast<std::uint64_t>(cx) << 32) ^ static_cast<std::uint64_t>(cy & 0xffffffff);
}

}  // namespace

void CutoffAssignment::solve(std::span<const Vec2> truth, std::span<const Vec2> estimates) {
  std::span<const Vec2> small = truth, large = estimates;
  truth_is_small_ = small.size() <= large.size();
  if (!truth_is_small_) std::swap(small, large);
  m_ = static_cast<int>(small.size());
  n_ = static_cast<int>(large.size());
  pairs_.clear();
  if (m_ == 0) return;

  const double cp = std::pow(c_, p_);
  if (static_cast<long>(m_) * n_ <= kWholeUpTo) {  // small: one Hungarian problem, no grid
    cost_.resize(static_cast<std::size_t>(m_) * n_);
    for (int i = 0; i < m_; ++i) {
      for (int j = 0; j < n_; ++j)
        cost_[i * n_ + j] = std::pow(std::min(c_, (small[i] - large[j]).norm()), p_);  // d_c^p
    }
    const std::span<const int> assigned = hungarian_.solve(cost_, m_, n_);
    for (int i = 0; i < m_; ++i) {
      const double cost = cost_[i * n_ + assigned[i]];
      if (cost < cp)
        pairs_.push_back(
            {truth_is_small_ ? i : assigned[i], truth_is_small_ ? assigned[i] : i, cost});
    }
    if (!truth_is_small_) {
      std::sort(pairs_.begin(), pairs_.end(),
                [](const Pair& a, const Pair& b) { return a.truth < b.truth; });
    }
    return;
  }

  // Edges: the pairs closer than c, found through a grid of cells of side c over the large set
  // (a pair closer than c lies in neighbouring cells). Non-finite points have no edge.
  std::unordered_map<std::uint64_t, std::vector<int>> grid;
  auto cellOf = [&](const Vec2& p) {
    return std::pair<std::int64_t, std::int64_t>{static_cast<std::int64_t>(std::floor(p.x() / c_)),
                                                 static_cast<std::int64_t>(std::floor(p.y() / c_))};
  };
  auto usable = [&](const Vec2& p) { return p.allFinite() && p.cwiseAbs().maxCoeff() < 1e15; };
  for (int j = 0; j < n_; ++j) {
    if (!usable(large[j])) continue;
    const auto [cx, cy] = cellOf(large[j]);
    grid[cellKey(cx, cy)].push_back(j);
  }
  std::vector<int> parent(static_cast<std::size_t>(m_ + n_));
  std::iota(parent.begin(), parent.end(), 0);
  edges_.clear();
  for (int i = 0; i < m_; ++i) {
    if (!usable(small[i])) continue;
    const auto [cx, cy] = cellOf(small[i]);
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        const auto cell = grid.find(cellKey(cx + dx, cy + dy));
        if (cell == grid.end()) continue;
        for (const int j : cell->second) {
          if (!((small[i] - large[j]).norm() < c_)) continue;
          edges_.push_back({i, j});
          parent[findRoot(parent, i)] = findRoot(parent, m_ + j);
        }
      }
    }
  }

  // Each connected component of the edge graph is its own cut-off assignment: a pair across
  // components costs c^p, as leaving both points unassigned does, so the components' optimal
  // matchings together are optimal (see the header).
  std::unordered_map<int, std::pair<std::vector<int>, std::vector<int>>> components;
  std::vector<char> in_component(static_cast<std::size_t>(m_ + n_), 0);
  for (const auto& [i, j] : edges_) {
    auto& [rows, cols] = components[findRoot(parent, i)];
    if (!in_component[i]) {
      in_component[i] = 1;
      rows.push_back(i);
    }
    if (!in_component[m_ + j]) {
      in_component[m_ + j] = 1;
      cols.push_back(j);
    }
  }
  std::vector<int> roots;
  for (const auto& entry : components) roots.push_back(entry.first);
  std::sort(roots.begin(), roots.end());  // a fixed order: the same sums on every platform
  for (const int root : roots) {
    auto& [rows, cols] = components[root];
    std::sort(rows.begin(), rows.end());
    std::sort(cols.begin(), cols.end());
    const bool rows_small = rows.size() <= cols.size();
    const std::vector<int>& r = rows_small ? rows : cols;
    const std::vector<int>& c = rows_small ? cols : rows;
    const int nr = static_cast<int>(r.size()), nc = static_cast<int>(c.size());
    cost_.resize(static_cast<std::size_t>(nr) * nc);
    for (int a = 0; a < nr; ++a) {
      for (int b = 0; b < nc; ++b) {
        const Vec2& x = rows_small ? small[r[a]] : small[c[b]];
        const Vec2& y = rows_small ? large[c[b]] : large[r[a]];
        cost_[static_cast<std::size_t>(a) * nc + b] = std::pow(std::min(c_, (x - y).norm()), p_);
      }
    }
    const std::span<const int> assigned = hungarian_.solve(cost_, nr, nc);
    for (int a = 0; a < nr; ++a) {
      const double cost = cost_[static_cast<std::size_t>(a) * nc + assigned[a]];
      if (!(cost < cp)) continue;  // at the cut-off: as good as unassigned
      const int i = rows_small ? r[a] : c[assigned[a]];
      const int j = rows_small ? c[assigned[a]] : r[a];
      pairs_.push_back({truth_is_small_ ? i : j, truth_is_small_ ? j : i, cost});
    }
  }
  std::sort(pairs_.begin(), pairs_.end(),
            [](const Pair& a, const Pair& b) { return a.truth < b.truth; });
}

double CutoffAssignment::penalised(double penalty_per_point) const {
  // Σ over the m small points of min(c, d)^p, plus the penalty for each of the n − m left over:
  // the small points without a pair closer than c are assigned at the cut-off, c^p.
  const double cp = std::pow(c_, p_);
  double total = penalty_per_point * (n_ - m_) + cp * (m_ - static_cast<int>(pairs_.size()));
  for (const Pair& pair : pairs_) total += pair.cost;
  return total;
}

double CutoffAssignment::ospa() const {
  if (n_ == 0) return 0.0;
  if (m_ == 0) return c_;
  return std::pow(penalised(std::pow(c_, p_)) / n_, 1.0 / p_);
}

double CutoffAssignment::gospa() const {
  return std::pow(penalised(0.5 * std::pow(c_, p_)), 1.0 / p_);  // c^p/α per miss, α = 2
}

CutoffAssignment::Parts CutoffAssignment::parts() const {
  Parts parts;
  const int matched = static_cast<int>(pairs_.size());  // pairs closer than c
  for (const Pair& pair : pairs_) parts.localisation += pair.cost;
  const int truths = truth_is_small_ ? m_ : n_;
  const int estimates = truth_is_small_ ? n_ : m_;
  parts.missed = truths - matched;
  parts.false_estimates = estimates - matched;
  return parts;
}

}  // namespace canopy::metrics
