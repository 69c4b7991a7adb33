#include "render/trails.h"

namespace canopy::render {

void TargetTrails::add(const world::WorldSnapshot& truth) {
  if (truth.targets.size() != points_.size()) {
    times_.clear();
    points_.assign(truth.targets.size(), {});
  }
  std::size_t old = 0;
  while (old < times_.size() && times_[old] < truth.time - seconds_) ++old;
  times_.erase(times_.begin(), times_.begin() + static_cast<std::ptrdiff_t>(old));
  times_.push_back(truth.time);
  for (std::size_t t = 0; t < points_.size(); ++t) {
    points_[t].erase(points_[t].begin(), points_[t].begin() + static_cast<std::ptrdiff_t>(old));
    points_[t].push_back(truth.targets[t].position);
  }
}

const std::vector<Vec2>& TargetTrails::trail(int target) const {
  static const std::vector<Vec2> kNone;
  return target >= 0 && target < targets() ? points_[target] : kNone;
}

}  // namespace canopy::render
