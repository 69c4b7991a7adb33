#include "agents/fusion/hungarian.h"

#include <cstddef>
#include <limits>

namespace canopy::agents::fusion {

std::span<const int> Hungarian::solve(std::span<const double> cost, int rows, int cols) {
  row_col_.assign(static_cast<std::size_t>(rows > 0 && rows <= cols ? rows : 0), -1);
  if (rows <= 0 || rows > cols) return row_col_;
  const std::size_t row_count = static_cast<std::size_t>(rows) + 1;
  const std::size_t col_count = static_cast<std::size_t>(cols) + 1;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  row_potential_.assign(row_count, 0.0);
  col_potential_.assign(col_count, 0.0);
  col_row_.assign(col_count, 0);
  prev_col_.assign(col_count, 0);
  auto reduced = [&](int r, int c) {  // c(r, c) − u_r − v_c ≥ 0 on every column of the tree
    return cost[static_cast<std::size_t>(r - 1) * cols + (c - 1)] - row_potential_[r] -
           col_potential_[c];
  };

  // Add the rows one at a time; each addition grows an alternating tree from the new row by
  // Dijkstra on reduced costs until it reaches a free column, then flips the path. The dual
  // update keeps every reduced cost non-negative and every assigned pair tight.
  for (int r = 1; r <= rows; ++r) {
    col_row_[0] = r;
    int col = 0;
    min_slack_.assign(col_count, kInf);
    visited_.assign(col_count, 0);
    do {
      visited_[col] = 1;
      const int row = col_row_[col];
      double delta = kInf;
      int next = 0;
      for (int c = 1; c <= cols; ++c) {
        if (visited_[c]) continue;
        const double slack = reduced(row, c);
        if (slack < min_slack_[c]) {
          min_slack_[c] = slack;
          prev_col_[c] = col;
        }
        if (min_slack_[c] < delta) {
          delta = min_slack_[c];
          next = c;
        }
      }
      for (int c = 0; c <= cols; ++c) {
        if (visited_[c]) {
          row_potential_[col_row_[c]] += delta;
          col_potential_[c] -= delta;
        } else {
          min_slack_[c] -= delta;
        }
      }
      col = next;
    } while (col_row_[col] != 0);
    while (col != 0) {  // flip the augmenting path back to the root
      const int prev = prev_col_[col];
      col_row_[col] = col_row_[prev];
      col = prev;
    }
  }
  for (int c = 1; c <= cols; ++c) {
    if (col_row_[c] != 0) row_col_[col_row_[c] - 1] = c - 1;
  }
  return row_col_;
}

void GatedAssignment::solve(std::span<const double> cost, int rows, int cols, double gate,
                            std::vector<AssignedPair>& pairs) {
  if (rows <= 0 || cols <= 0) return;
  const int n = rows + cols;
  const double half_gate = 0.5 * gate;
  // Any assignment that uses a forbidden entry costs more than leaving everything unassigned
  // ((rows + cols) · gate / 2), so the optimum never uses one.
  const double forbidden = (n + 1) * (gate + 1.0);
  augmented_.assign(static_cast<std::size_t>(n) * n, forbidden);
  auto at = [&](int r, int c) -> double& {
    return augmented_[static_cast<std::size_t>(r) * n + c];
  };
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      const double value = cost[static_cast<std::size_t>(r) * cols + c];
      if (value <= gate) at(r, c) = value;  // false for NaN and +∞ too
    }
    at(r, cols + r) = half_gate;  // row r left unassigned
  }
  for (int c = 0; c < cols; ++c) {
    at(rows + c, c) = half_gate;                                  // column c left unassigned
    for (int r = 0; r < rows; ++r) at(rows + c, cols + r) = 0.0;  // dummy meets dummy
  }
  const std::span<const int> col_of = hungarian_.solve(augmented_, n, n);
  for (int r = 0; r < rows; ++r) {
    const int c = col_of[r];
    if (c < 0 || c >= cols) continue;
    const double value = cost[static_cast<std::size_t>(r) * cols + c];
    if (value <= gate) pairs.push_back({r, c, value});
  }
}

}  // namespace canopy::agents::fusion
