#include "agents/tracking/known_people.h"

#include <algorithm>
#include <cmath>

namespace canopy::agents::tracking {

void boundKnownPerson(TargetGaussian& g, const Aabb& area, double walk_speed, bool lost) {
  const double v2 = walk_speed * walk_speed;
  // σ²_max per component: x, y (uniform over the area), vx, vy (the walking speed).
  const Vec4 bound(area.width() * area.width() / 12.0, area.height() * area.height() / 12.0, v2,
                   v2);
  Vec4 d = Vec4::Ones();
  bool scaled = false;
  for (int i = 0; i < 4; ++i) {
    if (g.P(i, i) > bound(i)) {
      d(i) = std::sqrt(bound(i) / g.P(i, i));  // D_ii = σ_max,i / σ_i < 1
      scaled = true;
    }
  }
  if (scaled) g.P = d.asDiagonal() * g.P * d.asDiagonal();  // P ← D P D
  if (!lost) return;
  g.x(0) = std::clamp(g.x(0), area.lo.x(), area.hi.x());
  g.x(1) = std::clamp(g.x(1), area.lo.y(), area.hi.y());
  const double speed = g.x.tail<2>().norm();
  if (speed > walk_speed) g.x.tail<2>() *= walk_speed / speed;
}

}  // namespace canopy::agents::tracking
