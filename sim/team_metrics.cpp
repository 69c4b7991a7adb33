#include "sim/team_metrics.h"

#include <Eigen/Cholesky>
#include <algorithm>

namespace canopy::sim {

TeamFigures TeamMetrics::compute(std::span<const Vec2> truth,
                                 std::span<const agents::AgentBelief> beliefs,
                                 std::vector<char>* held_by) {
  // The team's estimate set: per key, the copy with the least tr(P_pos) (agents in index order,
  // so a tie keeps the lower index).
  best_.clear();
  for (const agents::AgentBelief& belief : beliefs) {
    for (const agents::TrackEstimate& track : belief.tracks) {
      const agents::TargetGaussian& g = track.belief;
      best_.push_back({track.key, g.x.head<2>(), g.P(0, 0) + g.P(1, 1), g.P.topLeftCorner<2, 2>()});
    }
  }
  std::stable_sort(best_.begin(), best_.end(),
                   [](const Best& a, const Best& b) { return a.key < b.key; });
  std::size_t out = 0;
  for (std::size_t k = 0; k < best_.size(); ++k) {
    if (out > 0 && best_[out - 1].key == best_[k].key) {
      if (best_[k].trace < best_[out - 1].trace) best_[out - 1] = best_[k];
      continue;
    }
    best_[out++] = best_[k];
  }
  best_.resize(out);
  points_.clear();
  for (const Best& b : best_) points_.push_back(b.position);

  assignment_.solve(truth, points_);
  TeamFigures figures;
  figures.ospa = assignment_.ospa();
  figures.gospa = assignment_.gospa();
  figures.estimates = static_cast<int>(best_.size());
  if (held_by != nullptr) held_by->assign(truth.size(), 0);
  const double held_cost = kHeldDistance * kHeldDistance;  // d^p with p = 2
  for (const metrics::CutoffAssignment::Pair& pair : assignment_.pairs()) {
    if (pair.cost > held_cost) continue;
    const Best& estimate = best_[pair.estimate];
    const Vec2 dp = truth[pair.truth] - estimate.position;
    const Eigen::LDLT<Mat2> ldlt(estimate.P);
    if (ldlt.info() != Eigen::Success || !(dp.dot(ldlt.solve(dp)) <= kHeldGate)) continue;
    ++figures.held;
    if (held_by != nullptr) (*held_by)[pair.truth] = 1;
  }
  return figures;
}

}  // namespace canopy::sim
