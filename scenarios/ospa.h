#pragma once
// OSPA, the optimal sub-pattern assignment distance between a set of true positions and a set
// of estimates (Schuhmacher, Vo & Vo 2008), the tracking-quality metric of summary.json.
#include <span>
#include <vector>

#include "agents/fusion/hungarian.h"
#include "core/types.h"

namespace canopy::scenarios {

/// OSPA of order p with cut-off c (m), for |X| = m ≤ n = |Y| (else swap):
///   d = ( (1/n) · ( min_π Σ_{i≤m} min(c, |x_i − y_π(i)|)^p + c^p · (n − m) ) )^{1/p},
/// 0 when both sets are empty and c when exactly one is.
class Ospa {
 public:
  Ospa(double cutoff = 50.0, double order = 2.0) : c_(cutoff), p_(order) {}
  double operator()(std::span<const Vec2> truth, std::span<const Vec2> estimates);

 private:
  double c_, p_;
  agents::fusion::Hungarian hungarian_;
  std::vector<double> cost_;  // row-major m × n, reused
};

}  // namespace canopy::scenarios
