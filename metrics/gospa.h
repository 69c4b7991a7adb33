#pragma once
// GOSPA, the generalised OSPA distance (Rahmathullah, García-Fernández & Svensson 2017) with
// α = 2: unlike OSPA it is not normalised by the larger set, so each missed or false target adds
// c^p/2 and a poor localisation cannot look better than a missed target. Beside OSPA in
// summary.json, with the same cut-off and order (and the same assignment: CutoffAssignment).
#include <span>

#include "metrics/ospa.h"

namespace canopy::metrics {

/// GOSPA of order p, cut-off c (m), α = 2, for |X| = m ≤ n = |Y| (else swap):
///   d = ( min_π Σ_{i≤m} min(c, |x_i − y_π(i)|)^p + (c^p / 2) · (n − m) )^{1/p},
/// 0 when both sets are empty.
class Gospa {
 public:
  Gospa(double cutoff = 50.0, double order = 2.0) : assignment_(cutoff, order) {}
  double operator()(std::span<const Vec2> truth, std::span<const Vec2> estimates) {
    assignment_.solve(truth, estimates);
    return assignment_.gospa();
  }

 private:
  CutoffAssignment assignment_;
};

}  // namespace canopy::metrics
