#include "metrics/ospa.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>

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

CutoffAssignment::Sides CutoffAssignment::start(std::span<const Vec2> truth,
                                                std::span<const Vec2> estimates) {
  truth_is_small_ = truth.size() <= estimates.size();
  const Sides sides = truth_is_small_ ? Sides{truth, estimates} : Sides{estimates, truth};
  m_ = static_cast<int>(sides.small.size());
  n_ = static_cast<int>(sides.large.size());
  pairs_.clear();
  return sides;
}

void CutoffAssignment::solve(std::span<const Vec2> truth, std::span<const Vec2> estimates) {
  const auto [small, large] = start(truth, estimates);
  if (m_ == 0) return;

  if (static_cast<long>(m_) * n_ <= kWholeUpTo) {  // small: one Hungarian problem, no grid
    rows_.resize(m_);
    cols_.resize(n_);
    std::iota(rows_.begin(), rows_.end(), 0);
    std::iota(cols_.begin(), cols_.end(), 0);
    solvePart(small, large);
  } else {
    findEdges(small, large);
    solveByParts(small, large);
  }
  sortPairs();
}

void CutoffAssignment::solve(const CellGrid& truth_grid, std::span<const Vec2> estimates) {
  const std::span<const Vec2> truth = truth_grid.points();
  if (!truth_grid.usable() || truth_grid.side() != c_ ||
      static_cast<long>(truth.size()) * static_cast<long>(estimates.size()) <= kWholeUpTo) {
    solve(truth, estimates);
    return;
  }
  // Named spans, not a structured binding: the lambda below uses them (clang 14 cannot capture
  // bindings).
  const Sides sides = start(truth, estimates);
  const std::span<const Vec2> small = sides.small, large = sides.large;
  // The same edges as findEdges() finds (the same cells, the same distance test), in another
  // order, which the parts do not depend on.
  startEdges();
  for (int e = 0; e < static_cast<int>(estimates.size()); ++e) {
    if (!CellGrid::searchable(estimates[e])) continue;
    truth_grid.forEachNear(estimates[e], [&](int t) {
      if (truth_is_small_) {
        join(small, large, t, e);
      } else {
        join(small, large, e, t);
      }
    });
  }
  solveByParts(small, large);
  sortPairs();
}

void CutoffAssignment::sortPairs() {
  std::sort(pairs_.begin(), pairs_.end(),
            [](const Pair& a, const Pair& b) { return a.truth < b.truth; });
}

void CutoffAssignment::startEdges() {
  parent_.resize(static_cast<std::size_t>(m_ + n_));
  std::iota(parent_.begin(), parent_.end(), 0);
  edges_.clear();
}

void CutoffAssignment::join(std::span<const Vec2> small, std::span<const Vec2> large, int i,
                            int j) {
  if (!((small[i] - large[j]).norm() < c_)) return;
  edges_.push_back({0, i, j});
  parent_[findRoot(parent_, i)] = findRoot(parent_, m_ + j);
}

void CutoffAssignment::findEdges(std::span<const Vec2> small, std::span<const Vec2> large) {
  // The pairs closer than c, found through a grid of cells of side c over the large set (a pair
  // closer than c lies in neighbouring cells), kept as (cell, index) sorted by cell. Non-finite
  // points have no edge.
  auto cellOf = [&](const Vec2& p) {
    return std::pair<std::int64_t, std::int64_t>{static_cast<std::int64_t>(std::floor(p.x() / c_)),
                                                 static_cast<std::int64_t>(std::floor(p.y() / c_))};
  };
  cells_.clear();
  for (int j = 0; j < n_; ++j) {
    if (!CellGrid::searchable(large[j])) continue;
    const auto [cx, cy] = cellOf(large[j]);
    cells_.push_back({cellKey(cx, cy), j});
  }
  std::sort(cells_.begin(), cells_.end());
  startEdges();
  for (int i = 0; i < m_; ++i) {
    if (!CellGrid::searchable(small[i])) continue;
    const auto [cx, cy] = cellOf(small[i]);
    // Per column x, the cells (x, y−1), (x, y), (x, y+1) in the order of their keys (by cell,
    // then index) are one run of cells_ found by one search, unless y's low 32 bits (all the key
    // keeps of y) wrap between y − 1 and y + 1: then one cell at a time, in the same order.
    const auto low = static_cast<std::uint32_t>(cy & 0xffffffff);
    const bool one_run = low != 0 && low != 0xffffffffU;
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      for (std::int64_t dy = one_run ? 0 : -1; dy <= (one_run ? 0 : 1); ++dy) {
        const std::uint64_t first = cellKey(cx + dx, cy + (one_run ? -1 : dy));
        const std::uint64_t last = cellKey(cx + dx, cy + (one_run ? 1 : dy));
        auto cell = std::lower_bound(cells_.begin(), cells_.end(), std::pair{first, 0});
        for (; cell != cells_.end() && cell->first <= last; ++cell)
          join(small, large, i, cell->second);
      }
    }
  }
}

void CutoffAssignment::solveByParts(std::span<const Vec2> small, std::span<const Vec2> large) {
  // Each connected component of the edge graph is its own cut-off assignment: a pair across
  // components costs c^p, as leaving both points unassigned does, so the components' optimal
  // matchings together are optimal (see the header). Each part's rows and columns in index order:
  // the same sums on every platform, whatever order the edges were found in. The edges by root,
  // by a stable counting sort.
  root_start_.assign(parent_.size() + 1, 0);
  for (Edge& edge : edges_) {
    edge.root = findRoot(parent_, edge.small);
    ++root_start_[edge.root + 1];
  }
  std::partial_sum(root_start_.begin(), root_start_.end(), root_start_.begin());
  by_root_.resize(edges_.size());
  for (const Edge& edge : edges_) by_root_[root_start_[edge.root]++] = edge;
  for (std::size_t first = 0; first < by_root_.size();) {
    std::size_t last = first;
    rows_.clear();
    cols_.clear();
    for (; last < by_root_.size() && by_root_[last].root == by_root_[first].root; ++last) {
      rows_.push_back(by_root_[last].small);
      cols_.push_back(by_root_[last].large);
    }
    for (std::vector<int>* side : {&rows_, &cols_}) {
      std::sort(side->begin(), side->end());
      side->erase(std::unique(side->begin(), side->end()), side->end());
    }
    solvePart(small, large);
    first = last;
  }
}

void CutoffAssignment::solvePart(std::span<const Vec2> small, std::span<const Vec2> large) {
  const double cp = std::pow(c_, p_);
  // The smaller side of the part as the Hungarian problem's rows.
  const bool rows_small = rows_.size() <= cols_.size();
  const std::vector<int>& r = rows_small ? rows_ : cols_;
  const std::vector<int>& c = rows_small ? cols_ : rows_;
  const int nr = static_cast<int>(r.size()), nc = static_cast<int>(c.size());
  cost_.resize(static_cast<std::size_t>(nr) * nc);
  for (int a = 0; a < nr; ++a) {
    for (int b = 0; b < nc; ++b) {
      const Vec2& x = rows_small ? small[r[a]] : small[c[b]];
      const Vec2& y = rows_small ? large[c[b]] : large[r[a]];
      const double d = (x - y).norm();
      cost_[static_cast<std::size_t>(a) * nc + b] = d < c_ ? std::pow(d, p_) : cp;  // min(c, d)^p
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
