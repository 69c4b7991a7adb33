#include "metrics/ospa.h"

#include <algorithm>
#include <cmath>

namespace canopy::metrics {

void CutoffAssignment::solve(std::span<const Vec2> truth, std::span<const Vec2> estimates) {
  std::span<const Vec2> small = truth, large = estimates;
  truth_is_small_ = small.size() <= large.size();
  if (!truth_is_small_) std::swap(small, large);
  m_ = static_cast<int>(small.size());
  n_ = static_cast<int>(large.size());
  assignment_ = {};
  if (m_ == 0) return;
  cost_.resize(static_cast<std::size_t>(m_) * n_);
  for (int i = 0; i < m_; ++i) {
    for (int j = 0; j < n_; ++j) {
      cost_[i * n_ + j] = std::pow(std::min(c_, (small[i] - large[j]).norm()), p_);  // d_c^p
    }
  }
  assignment_ = hungarian_.solve(cost_, m_, n_);
}

double CutoffAssignment::penalised(double penalty_per_point) const {
  double total = penalty_per_point * (n_ - m_);  // cardinality penalty
  for (int i = 0; i < m_; ++i) total += cost_[i * n_ + assignment_[i]];
  return total;
}

double CutoffAssignment::ospa() const {
  if (n_ == 0) return 0.0;
  if (m_ == 0) return c_;
  return std::pow(penalised(std::pow(c_, p_)) / n_, 1.0 / p_);
}

double CutoffAssignment::gospa() const {
  return std::pow(penalised(0.5 * std::pow(c_, p_)), 1.0 / p_);  // c^p/α per miss, α = 2
}

CutoffAssignment::Parts CutoffAssignment::parts() const {
  Parts parts;
  int matched = 0;  // pairs closer than c
  const double c_p = std::pow(c_, p_);
  for (int i = 0; i < m_; ++i) {
    const double cost = cost_[i * n_ + assignment_[i]];
    if (cost < c_p) {
      parts.localisation += cost;
      ++matched;
    }
  }
  const int truths = truth_is_small_ ? m_ : n_;
  const int estimates = truth_is_small_ ? n_ : m_;
  parts.missed = truths - matched;
  parts.false_estimates = estimates - matched;
  return parts;
}

}  // namespace canopy::metrics
