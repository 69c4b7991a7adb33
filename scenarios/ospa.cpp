#include "scenarios/ospa.h"

#include <algorithm>
#include <cmath>

namespace canopy::scenarios {

double Ospa::operator()(std::span<const Vec2> truth, std::span<const Vec2> estimates) {
  std::span<const Vec2> small = truth, large = estimates;
  if (small.size() > large.size()) std::swap(small, large);
  const int m = static_cast<int>(small.size()), n = static_cast<int>(large.size());
  if (n == 0) return 0.0;
  if (m == 0) return c_;
  cost_.resize(static_cast<std::size_t>(m) * n);
  for (int i = 0; i < m; ++i) {
    for (int j = 0; j < n; ++j) {
      cost_[i * n + j] = std::pow(std::min(c_, (small[i] - large[j]).norm()), p_);  // d_c^p
    }
  }
  const std::span<const int> assignment = hungarian_.solve(cost_, m, n);
  double total = std::pow(c_, p_) * (n - m);  // cardinality penalty
  for (int i = 0; i < m; ++i) total += cost_[i * n + assignment[i]];
  return std::pow(total / n, 1.0 / p_);
}

}  // namespace canopy::scenarios
