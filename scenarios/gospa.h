#pragma once
// GOSPA, the generalised OSPA distance (Rahmathullah, García-Fernández & Svensson 2017) with
// α = 2: unlike OSPA it is not normalised by the larger set, so each missed or false target adds
// c^p/2 and a poor localisation cannot look better than a missed target. Beside OSPA in
// summary.json, with the same cut-off and order.
#include <span>
#include <vector>

#include "agents/fusion/hungarian.h"
#include "core/types.h"

namespace canopy::scenarios {

/// GOSPA of order p, cut-off c (m), α = 2, for |X| = m ≤ n = |Y| (else swap):
///   d = ( min_π Σ_{i≤m} min(c, |x_i − y_π(i)|)^p + (c^p / 2) · (n − m) )^{1/p},
/// 0 when both sets are empty. With α = 2 an assignment beyond c costs c^p, the same as leaving
/// both points unassigned, so the cut-off assignment is also the optimal GOSPA assignment.
class Gospa {
 public:
  Gospa(double cutoff = 50.0, double order = 2.0) : c_(cutoff), p_(order) {}
  double operator()(std::span<const Vec2> truth, std::span<const Vec2> estimates);

 private:
  double c_, p_;
  agents::fusion::Hungarian hungarian_;
  std::vector<double> cost_;  // row-major m × n, reused
};

}  // namespace canopy::scenarios
