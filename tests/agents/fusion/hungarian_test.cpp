#include "agents/fusion/hungarian.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/random.h"

namespace canopy::agents::fusion {
namespace {

double at(const std::vector<double>& cost, int cols, int r, int c) {
  return cost[r * cols + c];
}

/// Least Σ cost over one-to-one maps rows → columns, by trying every map.
double bruteForceAssignment(const std::vector<double>& cost, int rows, int cols) {
  std::vector<int> col_of(rows, -1);
  std::vector<char> used(cols, 0);
  double best = std::numeric_limits<double>::infinity();
  auto search = [&](auto&& self, int r, double sum) -> void {
    if (r == rows) {
      best = std::min(best, sum);
      return;
    }
    for (int c = 0; c < cols; ++c) {
      if (used[c]) continue;
      used[c] = 1;
      self(self, r + 1, sum + at(cost, cols, r, c));
      used[c] = 0;
    }
  };
  search(search, 0, 0.0);
  return best;
}

/// Least Σ_pairs cost + gate/2 per unassigned row or column over every partial matching that
/// uses only pairs with cost ≤ gate.
double bruteForceGated(const std::vector<double>& cost, int rows, int cols, double gate) {
  std::vector<char> used(cols, 0);
  double best = std::numeric_limits<double>::infinity();
  auto search = [&](auto&& self, int r, double sum, int matched) -> void {
    if (r == rows) {
      best = std::min(best, sum + 0.5 * gate * (rows + cols - 2 * matched));
      return;
    }
    self(self, r + 1, sum, matched);  // row r unassigned
    for (int c = 0; c < cols; ++c) {
      if (used[c] || !(at(cost, cols, r, c) <= gate)) continue;
      used[c] = 1;
      self(self, r + 1, sum + at(cost, cols, r, c), matched + 1);
      used[c] = 0;
    }
  };
  search(search, 0, 0.0, 0);
  return best;
}

TEST(Hungarian, SolvesAHandExample) {
  // Rows pick columns 1, 0, 2: 1 + 2 + 2 = 5; every other permutation costs more.
  const std::vector<double> cost = {4, 1, 3,  //
                                    2, 0, 5,  //
                                    3, 2, 2};
  Hungarian solver;
  const auto col_of = solver.solve(cost, 3, 3);
  ASSERT_EQ(col_of.size(), 3u);
  EXPECT_EQ(col_of[0], 1);
  EXPECT_EQ(col_of[1], 0);
  EXPECT_EQ(col_of[2], 2);
}

TEST(Hungarian, MatchesBruteForceOnRandomMatrices) {
  RandomStream rng(20240611, "test.hungarian");
  Hungarian solver;  // reused: also checks that buffers from a larger problem do no harm
  for (int trial = 0; trial < 400; ++trial) {
    const int rows = 1 + static_cast<int>(rng.uniform() * 5);     // 1..5
    const int cols = rows + static_cast<int>(rng.uniform() * 3);  // rows..rows + 2
    const bool integral = trial % 2 == 0;                         // ties on half the trials
    std::vector<double> cost(rows * cols);
    for (double& value : cost) {
      value = integral ? std::floor(rng.uniform(0.0, 5.0)) : rng.uniform(-3.0, 10.0);
    }
    const auto col_of = solver.solve(cost, rows, cols);
    ASSERT_EQ(static_cast<int>(col_of.size()), rows);
    std::vector<char> used(cols, 0);
    double sum = 0.0;
    for (int r = 0; r < rows; ++r) {
      ASSERT_GE(col_of[r], 0);
      ASSERT_LT(col_of[r], cols);
      ASSERT_FALSE(used[col_of[r]]) << "column assigned twice";
      used[col_of[r]] = 1;
      sum += at(cost, cols, r, col_of[r]);
    }
    EXPECT_NEAR(sum, bruteForceAssignment(cost, rows, cols), 1e-9) << "trial " << trial;
  }
}

TEST(GatedAssignment, MatchesBruteForceOverGatedMatchings) {
  RandomStream rng(99, "test.gated_assignment");
  GatedAssignment solver;
  const double gate = 4.0;
  for (int trial = 0; trial < 400; ++trial) {
    const int rows = 1 + static_cast<int>(rng.uniform() * 5);  // any shape: rows > cols too
    const int cols = 1 + static_cast<int>(rng.uniform() * 5);
    std::vector<double> cost(rows * cols);
    for (double& value : cost) value = rng.uniform(0.0, 8.0);  // about half above the gate
    std::vector<AssignedPair> pairs;
    solver.solve(cost, rows, cols, gate, pairs);
    std::vector<char> row_used(rows, 0), col_used(cols, 0);
    double objective = 0.5 * gate * (rows + cols - 2 * static_cast<int>(pairs.size()));
    for (const AssignedPair& pair : pairs) {
      ASSERT_LE(pair.cost, gate);
      ASSERT_EQ(pair.cost, at(cost, cols, pair.row, pair.col));
      ASSERT_FALSE(row_used[pair.row] || col_used[pair.col]);
      row_used[pair.row] = col_used[pair.col] = 1;
      objective += pair.cost;
    }
    EXPECT_NEAR(objective, bruteForceGated(cost, rows, cols, gate), 1e-9) << "trial " << trial;
  }
}

TEST(GatedAssignment, NeverAcceptsANonGatedPairThatTheHungarianPrefers) {
  // A full assignment must use (0, 1) + (1, 0) = 52 < (0, 0) + (1, 1) = 101, so the plain
  // Hungarian takes the pair (0, 1) at cost 50, far above the gate (the reference simulator's
  // bug). The gated assignment keeps only (0, 0): 1 + 9.21 < 2 + 9.21 < 52.
  const std::vector<double> cost = {1.0, 50.0,  //
                                    2.0, 100.0};
  Hungarian plain;
  const auto col_of = plain.solve(cost, 2, 2);
  ASSERT_EQ(col_of[0], 1);
  ASSERT_EQ(col_of[1], 0);

  GatedAssignment gated;
  std::vector<AssignedPair> pairs;
  gated.solve(cost, 2, 2, 9.21, pairs);
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs[0].row, 0);
  EXPECT_EQ(pairs[0].col, 0);
}

TEST(GatedAssignment, TreatsInfiniteAndNanCostsAsForbidden) {
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<double> cost = {inf, std::nan(""), 3.0, inf};
  GatedAssignment gated;
  std::vector<AssignedPair> pairs;
  gated.solve(cost, 2, 2, 9.21, pairs);
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs[0].row, 1);
  EXPECT_EQ(pairs[0].col, 0);
}

}  // namespace
}  // namespace canopy::agents::fusion
