#include "agents/tracking/jpda_solver.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/random.h"

namespace canopy::agents::tracking {
namespace {

// Second method: brute force over every tuple (a_0, …, a_{n−1}), a_t ∈ {miss, 0..m−1}, keeping
// the tuples where no measurement is used twice and every (t, a_t) is gated.
std::vector<double> bruteForce(int tracks, int measurements, const std::vector<GatedPair>& pairs) {
  std::vector<std::vector<int>> pair_of(tracks, std::vector<int>(measurements, -1));
  for (int p = 0; p < static_cast<int>(pairs.size()); ++p) {
    pair_of[pairs[p].track][pairs[p].measurement] = p;
  }
  std::vector<double> sum(pairs.size(), 0.0);
  double total = 0.0;
  std::vector<int> a(tracks, -1);
  while (true) {
    double w = 1.0;
    std::vector<bool> used(measurements, false);
    bool feasible = true;
    for (int t = 0; t < tracks && feasible; ++t) {
      if (a[t] < 0) continue;
      const int p = pair_of[t][a[t]];
      feasible = p >= 0 && !used[a[t]];
      if (feasible) {
        used[a[t]] = true;
        w *= std::exp(pairs[p].log_ratio);
      }
    }
    if (feasible) {
      total += w;
      for (int t = 0; t < tracks; ++t) {
        if (a[t] >= 0) sum[pair_of[t][a[t]]] += w;
      }
    }
    int t = 0;  // next tuple, odometer style
    while (t < tracks && ++a[t] == measurements) a[t++] = -1;
    if (t == tracks) break;
  }
  for (double& s : sum) s /= total;
  return sum;
}

TEST(JpdaSolver, GateThresholdIsChiSquareQuantile) {
  EXPECT_NEAR(gateThreshold(0.98), 7.8240460108562, 1e-9);       // −2 ln 0.02
  EXPECT_NEAR(std::exp(-gateThreshold(0.9) / 2.0), 0.1, 1e-15);  // χ²₂ tail e^{−γ/2} = 1 − P_G
}

TEST(JpdaSolver, SharedMeasurementSplitsProbability) {
  // Events: {}, {(1,z)}, {(2,z)} with weights 1, r₁, r₂.
  const double r1 = 3.0, r2 = 1.5;
  const std::vector<GatedPair> pairs{{0, 0, std::log(r1)}, {1, 0, std::log(r2)}};
  std::vector<double> beta(2);
  JpdaSolver solver;
  EXPECT_TRUE(solver.solve(2, 1, pairs, 10000, beta));
  EXPECT_NEAR(beta[0], r1 / (1.0 + r1 + r2), 1e-15);
  EXPECT_NEAR(beta[1], r2 / (1.0 + r1 + r2), 1e-15);
}

TEST(JpdaSolver, LoneTrackIsPda) {
  const std::vector<double> r{0.5, 2.0, 7.0};
  std::vector<GatedPair> pairs;
  for (int j = 0; j < 3; ++j) pairs.push_back({0, j, std::log(r[j])});
  std::vector<double> beta(3);
  JpdaSolver solver;
  EXPECT_TRUE(solver.solve(1, 3, pairs, 10000, beta));
  for (int j = 0; j < 3; ++j) EXPECT_NEAR(beta[j], r[j] / 10.5, 1e-15);  // r_j / (1 + Σ r)
}

TEST(JpdaSolver, CrossedPairsMatchHandFormula) {
  // Tracks a, b and measurements 1, 2, all gated. Events: {}, {a1}, {a2}, {b1}, {b2}, {a1, b2},
  // {a2, b1}. β_a1 = (r_a1 + r_a1 r_b2) / Z, Z = the sum of all seven weights.
  const double a1 = 4.0, a2 = 0.5, b1 = 2.0, b2 = 3.0;
  const std::vector<GatedPair> pairs{
      {0, 0, std::log(a1)}, {0, 1, std::log(a2)}, {1, 0, std::log(b1)}, {1, 1, std::log(b2)}};
  const double Z = 1.0 + a1 + a2 + b1 + b2 + a1 * b2 + a2 * b1;
  std::vector<double> beta(4);
  JpdaSolver solver;
  EXPECT_TRUE(solver.solve(2, 2, pairs, 7, beta));  // exactly 7 events fit a cap of 7
  EXPECT_NEAR(beta[0], (a1 + a1 * b2) / Z, 1e-15);
  EXPECT_NEAR(beta[1], (a2 + a2 * b1) / Z, 1e-15);
  EXPECT_NEAR(beta[2], (b1 + b1 * a2) / Z, 1e-15);
  EXPECT_NEAR(beta[3], (b2 + b2 * a1) / Z, 1e-15);

  // Beyond the cap: belief propagation, approximate on this loop but close.
  std::vector<double> approx(4);
  EXPECT_FALSE(solver.solve(2, 2, pairs, 6, approx));
  for (int p = 0; p < 4; ++p) EXPECT_NEAR(approx[p], beta[p], 0.03) << p;
}

TEST(JpdaSolver, EnumerationMatchesBruteForce) {
  RandomStream rng(7, "jpda_solver_test");
  for (int trial = 0; trial < 50; ++trial) {
    const int tracks = 1 + static_cast<int>(rng.uniform() * 5);
    const int measurements = 1 + static_cast<int>(rng.uniform() * 5);
    std::vector<GatedPair> pairs;
    for (int t = 0; t < tracks; ++t) {
      for (int j = 0; j < measurements; ++j) {
        if (rng.bernoulli(0.6)) pairs.push_back({t, j, rng.uniform(-3.0, 6.0)});
      }
    }
    std::vector<double> beta(pairs.size());
    JpdaSolver solver;
    ASSERT_TRUE(solver.solve(tracks, measurements, pairs, 1000000, beta));
    const std::vector<double> expected = bruteForce(tracks, measurements, pairs);
    for (std::size_t p = 0; p < pairs.size(); ++p) EXPECT_NEAR(beta[p], expected[p], 1e-12);
  }
}

TEST(JpdaSolver, PropagationIsExactOnTreeShapedClusters) {
  // A chain t0 – z0 – t1 – z1 – t2 has no cycle, so BP's marginals are exact.
  const std::vector<GatedPair> pairs{{0, 0, 1.0}, {1, 0, 0.3}, {1, 1, 2.0}, {2, 1, -0.5}};
  std::vector<double> exact(4), approx(4);
  JpdaSolver solver;
  ASSERT_TRUE(solver.solve(3, 2, pairs, 1000, exact));
  EXPECT_FALSE(solver.solve(3, 2, pairs, 1, approx));
  for (int p = 0; p < 4; ++p) EXPECT_NEAR(approx[p], exact[p], 1e-10);
}

TEST(JpdaSolver, ExtremeRatiosStayFinite) {
  // Likelihood ratios far beyond what a double holds (λ → 0) must not overflow.
  const std::vector<GatedPair> pairs{
      {0, 0, 900.0}, {0, 1, 850.0}, {1, 0, 905.0}, {1, 1, -900.0}, {2, 1, 800.0}};
  for (const long cap : {1000L, 1L}) {
    std::vector<double> beta(pairs.size());
    JpdaSolver solver;
    solver.solve(3, 2, pairs, cap, beta);
    for (const double b : beta) {
      EXPECT_TRUE(std::isfinite(b));
      EXPECT_GE(b, 0.0);
      EXPECT_LE(b, 1.0);
    }
    // The dominant event {(0,1), (1,0)} takes (almost) all the mass.
    EXPECT_NEAR(beta[1], 1.0, 1e-6) << cap;
    EXPECT_NEAR(beta[2], 1.0, 1e-6) << cap;
  }
}

}  // namespace
}  // namespace canopy::agents::tracking
