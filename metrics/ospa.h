#pragma once
// OSPA, the optimal sub-pattern assignment distance between a set of true positions and a set
// of estimates (Schuhmacher, Vo & Vo 2008), the tracking-quality metric of summary.json, and the
// assignment it shares with GOSPA (metrics/gospa.h).
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "agents/fusion/hungarian.h"
#include "core/types.h"
#include "metrics/cell_grid.h"

namespace canopy::metrics {

/// The cut-off assignment of two point sets, with m ≤ n the sizes of the smaller and the larger:
///   min_π Σ_{i≤m} min(c, |x_i − y_π(i)|)^p.
/// OSPA and GOSPA with α = 2 are both read off one solve (with α = 2 an assignment beyond c costs
/// c^p, the same as leaving both points unassigned, so the cut-off assignment is GOSPA's too).
///
/// Solved exactly by parts: the assignment's cost is c^p·m − Σ_pairs (c^p − d^p) over the pairs
/// closer than c, so it is a maximum-weight matching on the graph of those pairs, and a matching
/// is optimal when it is optimal on each connected component of that graph. Each component is
/// one Hungarian problem (its smaller side as rows), found through a grid of cells of side c. A
/// team of agents spread over a city has many small components: the work grows with the people
/// and tracks near each other, not with the square of everyone.
class CutoffAssignment {
 public:
  CutoffAssignment(double cutoff = 50.0, double order = 2.0) : c_(cutoff), p_(order) {}
  void solve(std::span<const Vec2> truth, std::span<const Vec2> estimates);
  /// The same solve, the truth's pairs found through its grid (cells of side c, built once for
  /// many solves against the same truth): the same bits as solve(truth.points(), estimates).
  void solve(const CellGrid& truth, std::span<const Vec2> estimates);
  double cutoff() const { return c_; }

  /// Of the last solve: ( (1/n) · (assignment + c^p · (n − m)) )^{1/p}; 0 when both sets are
  /// empty and c when exactly one is.
  double ospa() const;
  /// Of the last solve: ( assignment + (c^p / 2) · (n − m) )^{1/p}; 0 when both sets are empty.
  double gospa() const;

  /// GOSPA's parts (α = 2) of the last solve: gospa()^p = localisation + (c^p / 2)(missed + false),
  /// a pair assigned at distance ≥ c counting as one missed truth and one false estimate.
  struct Parts {
    double localisation = 0.0;  // Σ d^p over the pairs assigned closer than c (m^p)
    int missed = 0;             // truths with no estimate closer than c
    int false_estimates = 0;    // estimates with no truth closer than c
  };
  Parts parts() const;

  /// The pairs of the last solve closer than c (truth index, estimate index, d^p), by truth index.
  struct Pair {
    int truth = 0;
    int estimate = 0;
    double cost = 0.0;  // d^p
  };
  std::span<const Pair> pairs() const { return pairs_; }

 private:
  double penalised(double penalty_per_point) const;  // the penalty, then each assigned cost
  // The part small[rows_] × large[cols_]: its pairs closer than c join pairs_.
  void solvePart(std::span<const Vec2> small, std::span<const Vec2> large);
  struct Sides {
    std::span<const Vec2> small, large;  // the smaller set (the assignment's rows), the larger
  };
  // A new solve: which set is the smaller, m_, n_, and no pairs yet.
  Sides start(std::span<const Vec2> truth, std::span<const Vec2> estimates);
  void sortPairs();   // pairs_ by truth index
  void startEdges();  // no edges; each point its own component
  // edges_: the pairs closer than c, through a grid of cells over the large set.
  void findEdges(std::span<const Vec2> small, std::span<const Vec2> large);
  // The pair (small i, large j) when closer than c: an edge, and one component in parent_.
  void join(std::span<const Vec2> small, std::span<const Vec2> large, int i, int j);
  // Every connected component of edges_, each by solvePart().
  void solveByParts(std::span<const Vec2> small, std::span<const Vec2> large);

  double c_, p_;
  int m_ = 0, n_ = 0;
  bool truth_is_small_ = true;  // the truth is the smaller set (rows of the assignment)
  agents::fusion::Hungarian hungarian_;
  // Buffers kept between solves (a run solves one or more per step).
  std::vector<double> cost_;                          // one part's row-major costs
  std::vector<std::pair<std::uint64_t, int>> cells_;  // (grid cell, large index), sorted
  std::vector<int> parent_;                           // union-find over small, then large
  struct Edge {
    int root = 0;  // its component
    int small = 0, large = 0;
  };
  std::vector<Edge> edges_;       // pairs closer than c
  std::vector<Edge> by_root_;     // edges_ by component root (then as in edges_)
  std::vector<int> root_start_;   // per root, its first edge in by_root_ (a counting sort)
  std::vector<int> rows_, cols_;  // one part's small and large indices
  std::vector<Pair> pairs_;
};

/// OSPA of order p with cut-off c (m), for |X| = m ≤ n = |Y| (else swap):
///   d = ( (1/n) · ( min_π Σ_{i≤m} min(c, |x_i − y_π(i)|)^p + c^p · (n − m) ) )^{1/p},
/// 0 when both sets are empty and c when exactly one is.
class Ospa {
 public:
  Ospa(double cutoff = 50.0, double order = 2.0) : assignment_(cutoff, order) {}
  double operator()(std::span<const Vec2> truth, std::span<const Vec2> estimates) {
    assignment_.solve(truth, estimates);
    return assignment_.ospa();
  }

 private:
  CutoffAssignment assignment_;
};

}  // namespace canopy::metrics
