// The cut-off assignment solved by parts (connected components of the pairs closer than c)
// against the whole problem solved at once by the Hungarian method on min(c, d)^p, the way
// metrics/ospa.cpp solved it before: clustered and scattered point sets of many sizes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <span>
#include <vector>

#include "agents/fusion/hungarian.h"
#include "metrics/cell_grid.h"
#include "metrics/ospa.h"

namespace canopy::metrics {
namespace {

// The whole problem at once: Σ over the smaller set of min(c, d)^p at the optimum.
double wholeAssignment(const std::vector<Vec2>& a, const std::vector<Vec2>& b, double c, double p) {
  const std::vector<Vec2>& small = a.size() <= b.size() ? a : b;
  const std::vector<Vec2>& large = a.size() <= b.size() ? b : a;
  const int m = static_cast<int>(small.size()), n = static_cast<int>(large.size());
  std::vector<double> cost(static_cast<std::size_t>(m) * n);
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < n; ++j)
      cost[i * n + j] = std::pow(std::min(c, (small[i] - large[j]).norm()), p);
  agents::fusion::Hungarian hungarian;
  const std::span<const int> col = hungarian.solve(cost, m, n);
  double total = 0.0;
  for (int i = 0; i < m; ++i) total += cost[i * n + col[i]];
  return total;
}

TEST(CutoffParts, EqualsTheWholeAssignmentOnRandomSets) {
  std::mt19937_64 rng(20261207);
  const double c = 50.0, p = 2.0;
  for (int trial = 0; trial < 200; ++trial) {
    std::uniform_int_distribution<int> count(0, 40);
    const int m = count(rng), n = count(rng);
    // Groups of points around a few centres over a 600 m square, so some components are large.
    std::uniform_real_distribution<double> where(0.0, 600.0), near(-30.0, 30.0);
    std::vector<Vec2> centres(1 + trial % 6);
    for (Vec2& centre : centres) centre = Vec2(where(rng), where(rng));
    auto draw = [&](int k) {
      std::vector<Vec2> points;
      for (int i = 0; i < k; ++i)
        points.push_back(centres[i % centres.size()] + Vec2(near(rng), near(rng)));
      return points;
    };
    const std::vector<Vec2> truth = draw(m), estimates = draw(n);
    CutoffAssignment parts(c, p);
    parts.solve(truth, estimates);
    const int big = std::max(m, n), small = std::min(m, n);
    const double whole = wholeAssignment(truth, estimates, c, p);
    const double ospa = big == 0     ? 0.0
                        : small == 0 ? c
                                     : std::sqrt((whole + std::pow(c, p) * (big - small)) / big);
    const double gospa = std::sqrt(whole + 0.5 * std::pow(c, p) * (big - small));
    EXPECT_NEAR(parts.ospa(), ospa, 1e-9 * (1.0 + ospa)) << "trial " << trial;
    EXPECT_NEAR(parts.gospa(), gospa, 1e-9 * (1.0 + gospa)) << "trial " << trial;
    for (const CutoffAssignment::Pair& pair : parts.pairs()) {
      EXPECT_LT(pair.cost, std::pow(c, p));
      EXPECT_NEAR(pair.cost, (truth[pair.truth] - estimates[pair.estimate]).squaredNorm(), 1e-9);
    }
  }
}

// The parts found by brute force: every pair compared (no grid), components by a search over
// them, each solved as metrics/ospa.cpp solves a part (its smaller side as rows, indices in
// order, min(c, d)^p), pairs closer than c by truth index. The grid's runs of cells and its
// counting sort must give these pairs bit for bit.
std::vector<CutoffAssignment::Pair> bruteForceParts(const std::vector<Vec2>& truth,
                                                    const std::vector<Vec2>& estimates, double c,
                                                    double p) {
  const bool truth_small = truth.size() <= estimates.size();
  const std::vector<Vec2>& small = truth_small ? truth : estimates;
  const std::vector<Vec2>& large = truth_small ? estimates : truth;
  const int m = static_cast<int>(small.size()), n = static_cast<int>(large.size());
  auto usable = [](const Vec2& x) { return x.allFinite() && x.cwiseAbs().maxCoeff() < 1e15; };
  auto close = [&](int i, int j) {
    return usable(small[i]) && usable(large[j]) && (small[i] - large[j]).norm() < c;
  };
  std::vector<int> component(static_cast<std::size_t>(m + n), -1);
  std::vector<CutoffAssignment::Pair> pairs;
  agents::fusion::Hungarian hungarian;
  for (int seed = 0; seed < m; ++seed) {
    if (component[seed] >= 0) continue;
    std::vector<int> stack{seed}, rows, cols;
    component[seed] = seed;
    while (!stack.empty()) {  // nodes 0..m−1 small, m..m+n−1 large
      const int node = stack.back();
      stack.pop_back();
      (node < m ? rows : cols).push_back(node < m ? node : node - m);
      for (int other = 0; other < m + n; ++other) {
        if (component[other] >= 0 || (node < m) == (other < m)) continue;
        if (!(node < m ? close(node, other - m) : close(other, node - m))) continue;
        component[other] = seed;
        stack.push_back(other);
      }
    }
    if (cols.empty()) continue;
    std::sort(rows.begin(), rows.end());
    std::sort(cols.begin(), cols.end());
    const bool rows_small = rows.size() <= cols.size();
    const std::vector<int>& r = rows_small ? rows : cols;
    const std::vector<int>& k = rows_small ? cols : rows;
    const int nr = static_cast<int>(r.size()), nc = static_cast<int>(k.size());
    std::vector<double> cost(static_cast<std::size_t>(nr) * nc);
    for (int a = 0; a < nr; ++a) {
      for (int b = 0; b < nc; ++b) {
        const Vec2& x = rows_small ? small[r[a]] : small[k[b]];
        const Vec2& y = rows_small ? large[k[b]] : large[r[a]];
        cost[static_cast<std::size_t>(a) * nc + b] = std::pow(std::min(c, (x - y).norm()), p);
      }
    }
    const std::span<const int> assigned = hungarian.solve(cost, nr, nc);
    for (int a = 0; a < nr; ++a) {
      const double d = cost[static_cast<std::size_t>(a) * nc + assigned[a]];
      if (!(d < std::pow(c, p))) continue;
      const int i = rows_small ? r[a] : k[assigned[a]];
      const int j = rows_small ? k[assigned[a]] : r[a];
      pairs.push_back({truth_small ? i : j, truth_small ? j : i, d});
    }
  }
  std::sort(pairs.begin(), pairs.end(),
            [](const CutoffAssignment::Pair& a, const CutoffAssignment::Pair& b) {
              return a.truth < b.truth;
            });
  return pairs;
}

TEST(CutoffParts, PairsEqualBruteForceBitForBit) {
  std::mt19937_64 rng(20261208);
  // p read at run time, as the library reads it: a constant 2 would let the compiler turn
  // std::pow(d, 2) into d · d, whose last bit may differ from libm's pow.
  volatile double order = 2.0;
  const double c = 50.0, p = order;
  // Where the groups sit: around the origin (cells y = −1 and 0, whose keys are not
  // consecutive), in the middle of nowhere, and where a cell's y crosses a multiple of 2^32
  // (its key keeps the low 32 bits of y).
  const double wrap = 50.0 * 4294967296.0;
  const Vec2 origins[] = {Vec2(0, 0), Vec2(-3000, 7000), Vec2(1234.5, wrap), Vec2(-77, -wrap)};
  int compared = 0;
  for (int trial = 0; trial < 160; ++trial) {
    std::uniform_int_distribution<int> count(17, 70);  // m·n > 256: by parts
    const int m = count(rng), n = count(rng);
    std::uniform_real_distribution<double> where(-250.0, 250.0), near(-40.0, 40.0);
    const Vec2 origin = origins[trial % 4];
    std::vector<Vec2> centres(1 + trial % 7);
    for (Vec2& centre : centres) centre = origin + Vec2(where(rng), where(rng));
    auto draw = [&](int k) {
      std::vector<Vec2> points;
      for (int i = 0; i < k; ++i)
        points.push_back(centres[i % centres.size()] + Vec2(near(rng), near(rng)));
      return points;
    };
    std::vector<Vec2> truth = draw(m), estimates = draw(n);
    if (trial % 5 == 0) {  // points without edges
      truth[0] = Vec2(std::nan(""), 0.0);
      estimates[1] = Vec2(2e15, 0.0);
    }
    const bool spread = trial % 9 == 4;  // a person 60 000 km away: too wide a box for a grid
    if (spread) truth.back() = origin + Vec2(6e7, 0.0);
    const std::vector<CutoffAssignment::Pair> expected = bruteForceParts(truth, estimates, c, p);
    // Both ways of finding the pairs: a grid over the larger set, built for this solve, and the
    // people's grid, built once for many solves (sim/summary.cpp).
    CutoffAssignment parts(c, p), through_grid(c, p);
    parts.solve(truth, estimates);
    CellGrid truth_grid;
    truth_grid.build(truth, c);
    EXPECT_EQ(truth_grid.usable(), !spread) << "trial " << trial;
    through_grid.solve(truth_grid, estimates);
    for (const CutoffAssignment* solved : {&parts, &through_grid}) {
      ASSERT_EQ(solved->pairs().size(), expected.size()) << "trial " << trial;
      for (std::size_t k = 0; k < expected.size(); ++k) {
        EXPECT_EQ(solved->pairs()[k].truth, expected[k].truth) << "trial " << trial;
        EXPECT_EQ(solved->pairs()[k].estimate, expected[k].estimate) << "trial " << trial;
        EXPECT_EQ(solved->pairs()[k].cost, expected[k].cost) << "trial " << trial;  // same bits
      }
    }
    EXPECT_EQ(through_grid.ospa(), parts.ospa()) << "trial " << trial;
    EXPECT_EQ(through_grid.gospa(), parts.gospa()) << "trial " << trial;
    compared += static_cast<int>(expected.size());
  }
  EXPECT_GT(compared, 2000);  // the trials paired many points
}

}  // namespace
}  // namespace canopy::metrics
