#include "sim/team_metrics.h"

#include <Eigen/Cholesky>
#include <algorithm>

namespace canopy::sim {

TeamFigures TeamMetrics::compute(std::span<const Vec2> truth,
                                 std::span<const agents::AgentBelief> beliefs,
                                 std::vector<char>* held_by) {
  // The team's estimate set: per key, the copy with the least tr(P_pos). The copies are visited
  // agent by agent (in index order), and a later copy replaces the kept one only when its trace is
  // strictly less, so a tie keeps the lower index. Then the set in key order.
  best_.clear();
  slot_of_key_.clear();
  for (const agents::AgentBelief& belief : beliefs) {
    for (const agents::TrackEstimate& track : belief.tracks) {
      const agents::TargetGaussian& g = track.belief;
      const Best copy{track.key, g.x.head<2>(), g.P(0, 0) + g.P(1, 1), g.P.topLeftCorner<2, 2>()};
      const auto [slot, inserted] = slot_of_key_.try_emplace(packed(track.key), best_.size());
      if (inserted) {
        best_.push_back(copy);
      } else if (copy.trace < best_[slot->second].trace) {
        best_[slot->second] = copy;
      }
    }
  }
  std::sort(best_.begin(), best_.end(),  // the keys are distinct
            [](const Best& a, const Best& b) { return a.key < b.key; });
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
