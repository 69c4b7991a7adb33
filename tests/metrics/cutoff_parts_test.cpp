// The cut-off assignment solved by parts (connected components of the pairs closer than c)
// against the whole problem solved at once by the Hungarian method on min(c, d)^p, the way
// metrics/ospa.cpp solved it before: clustered and scattered point sets of many sizes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "agents/fusion/hungarian.h"
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

}  // namespace
}  // namespace canopy::metrics
