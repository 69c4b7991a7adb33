#include "scenarios/gospa.h"

#include <algorithm>
#include <cmath>

namespace canopy::scenarios {

double Gospa::operator()(std::span<const Vec2> truth, std::span<const Vec2> estimates) {
  std::span<const Vec2> small = truth, large = estimates;
  if (small.size() > large.size()) std::swap(small, large);
  const int m = static_cast<int>(small.size()), n = static_cast<int>(large.size());
  double total = 0.5 * std::pow(c_, p_) * (n - m);  // c^p/α per missed or false target, α = 2
  if (m > 0) {
    cost_.resize(static_cast<std::size_t>(m) * n);
    for (int i = 0; i < m; ++i) {
      for (int j = 0; j < n; ++j)
        cost_[i * n + j] = std::pow(std::min(c_, (small[i] - large[j]).norm()), p_);
    }
    const std::span<const int> assignment = hungarian_.solve(cost_, m, n);
    for (int i = 0; i < m; ++i) total += cost_[i * n + assignment[i]];
  }
  return std::pow(total, 1.0 / p_);
}

}  // namespace canopy::scenarios
