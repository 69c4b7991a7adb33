#include "world/near_solids.h"

#include <algorithm>

namespace canopy::world {
NearSolids::NearSolids(const std::vector<TreeDef>& trees)
    : index_(trees), users_(trees.size(), 0) {}

void NearSolids::update(int robot, const Vec2& p, double radius, double travel,
                        std::vector<int>& added, std::vector<int>& removed) {
  if (robot >= static_cast<int>(near_.size())) near_.resize(robot + 1);
  Neighbourhood& n = near_[robot];
  if (n.valid && (p - n.anchor).norm() + travel <= n.skin) return;  // it cannot leave it yet

  n.valid = true;
  n.anchor = p;
  n.skin = std::max(kMinSkin, 2.0 * travel);
  const double reach = radius + n.skin + kFloatMargin;  // m
  const Vec2 half(reach, reach);
  scratch_.clear();
  index_.near(Aabb{p - half, p + half}, scratch_);  // ascending, each once

  // Walk the old and new lists together: in the new only → one more user; in the old only →
  // one fewer. A solid enters the world with its first user and leaves it with its last.
  std::size_t i = 0, j = 0;
  const std::vector<int>& old = n.solids;
  while (i < old.size() || j < scratch_.size()) {
    if (j == scratch_.size() || (i < old.size() && old[i] < scratch_[j])) {
      if (--users_[old[i]] == 0) {
        removed.push_back(old[i]);
        --held_;
      }
      ++i;
    } else if (i == old.size() || scratch_[j] < old[i]) {
      if (users_[scratch_[j]]++ == 0) {
        added.push_back(scratch_[j]);
        ++held_;
      }
      ++j;
    } else {
      ++i;
      ++j;
    }
  }
  n.solids.swap(scratch_);
}

}  // namespace canopy::world
