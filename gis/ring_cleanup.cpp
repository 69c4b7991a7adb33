#include "gis/ring_cleanup.h"

#include <algorithm>
#include <cmath>

namespace canopy::gis {

std::vector<Vec2> cleanRing(std::vector<Vec2> ring) {
  bool changed = true;
  while (changed && ring.size() >= 3) {
    changed = false;
    std::vector<Vec2> kept;
    for (const Vec2& p : ring) {
      if (!kept.empty() && (p - kept.back()).norm() < kRingWeld) {
        changed = true;
        continue;
      }
      kept.push_back(p);
    }
    while (kept.size() > 1 && (kept.front() - kept.back()).norm() < kRingWeld) {
      kept.pop_back();  // the closing point, or one next to the first
      changed = true;
    }
    ring = std::move(kept);
    const std::size_t n = ring.size();
    if (n < 3) break;
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2& a = ring[(i + n - 1) % n];
      const Vec2& b = ring[(i + 1) % n];
      const Vec2 e = b - a;
      // Distance from the vertex to the line a–b: |e × (v − a)| / |e|.
      const double off = std::abs(e.x() * (ring[i] - a).y() - e.y() * (ring[i] - a).x()) / e.norm();
      if (!(off >= kRingStraight)) {
        ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(i));
        changed = true;
        break;
      }
    }
  }
  return ring;
}

std::vector<Vec2> canonicalRing(std::vector<Vec2> ring) {
  if (ring.size() < 3) return ring;
  double twice_area = 0.0;  // shoelace
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Vec2& a = ring[i];
    const Vec2& b = ring[(i + 1) % ring.size()];
    twice_area += a.x() * b.y() - a.y() * b.x();
  }
  if (twice_area < 0.0) std::reverse(ring.begin(), ring.end());
  const auto least = std::min_element(ring.begin(), ring.end(), [](const Vec2& a, const Vec2& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  std::rotate(ring.begin(), least, ring.end());
  return ring;
}

}  // namespace canopy::gis
