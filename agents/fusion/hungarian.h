#pragma once
// Minimum-cost assignment (Kuhn 1955; Munkres 1957) in its shortest-augmenting-path form with
// dual potentials (Jonker & Volgenant 1987), and the gated assignment that track-to-track
// association builds on it.
#include <span>
#include <vector>

namespace canopy::agents::fusion {

/// Solves min Σ_r cost(r, col(r)) over one-to-one maps from rows to columns (rows ≤ cols),
/// O(rows² · cols). The buffers are kept between calls, so a solver reused every step stops
/// allocating once it has seen its largest problem.
class Hungarian {
 public:
  /// cost: row-major rows × cols, every entry finite. Returns col(r) for r = 0..rows − 1; the
  /// span stays valid until the next call. rows ≤ cols is the caller's duty (rows > cols: empty).
  std::span<const int> solve(std::span<const double> cost, int rows, int cols);

 private:
  // Indices are 1-based inside solve(): column 0 is the virtual root of each augmenting path.
  std::vector<double> row_potential_;  // u (rows + 1)
  std::vector<double> col_potential_;  // v (cols + 1)
  std::vector<double> min_slack_;      // least reduced cost reaching each column (cols + 1)
  std::vector<int> col_row_;           // row assigned to each column, 0 = none (cols + 1)
  std::vector<int> prev_col_;          // the column before each one on the augmenting path
  std::vector<char> visited_;          // columns in the current alternating tree
  std::vector<int> row_col_;           // the answer (rows)
};

/// One accepted pair of a gated assignment.
struct AssignedPair {
  int row = 0;
  int col = 0;
  double cost = 0.0;  // the pair's cost (for association: squared Mahalanobis distance)
};

/// The set of pairs with cost ≤ gate that minimises Σ_pairs cost + (gate / 2) per row or column
/// left unassigned. Leaving both ends of a pair unassigned costs exactly the gate, so a pair
/// above the gate is never accepted, whatever it would save elsewhere. Solved as a square
/// (rows + cols) Hungarian problem with one "unassigned" column per row and one "unassigned"
/// row per column.
class GatedAssignment {
 public:
  /// cost: row-major rows × cols; an entry above `gate` (or infinite, or NaN) is a forbidden pair.
  /// gate: finite and > 0. Appends the accepted pairs to `pairs` (sorted by row).
  void solve(std::span<const double> cost, int rows, int cols, double gate,
             std::vector<AssignedPair>& pairs);

 private:
  Hungarian hungarian_;
  std::vector<double> augmented_;  // (rows + cols)², row-major
};

}  // namespace canopy::agents::fusion
