#include "render/internal/label_space.h"

#include <algorithm>
#include <cmath>

namespace canopy::render::internal {

bool boxesOverlap(const Aabb& a, const Aabb& b) {
  return a.lo.x() < b.hi.x() && b.lo.x() < a.hi.x() && a.lo.y() < b.hi.y() && b.lo.y() < a.hi.y();
}

bool segmentHitsBox(const Vec2& a, const Vec2& b, const Aabb& box) {
  // Liang–Barsky: p(s) = a + s (b − a), s ∈ [0, 1], clipped against each slab of the box.
  double s0 = 0.0, s1 = 1.0;
  const Vec2 d = b - a;
  for (int axis = 0; axis < 2; ++axis) {
    if (std::abs(d[axis]) < 1e-12) {
      if (a[axis] < box.lo[axis] || a[axis] > box.hi[axis]) return false;
      continue;
    }
    double enter = (box.lo[axis] - a[axis]) / d[axis], leave = (box.hi[axis] - a[axis]) / d[axis];
    if (enter > leave) std::swap(enter, leave);
    s0 = std::max(s0, enter);
    s1 = std::min(s1, leave);
    if (s0 > s1) return false;
  }
  return true;
}

bool discHitsBox(const Vec2& centre, double radius, const Aabb& box) {
  const Vec2 nearest(std::clamp(centre.x(), box.lo.x(), box.hi.x()),
                     std::clamp(centre.y(), box.lo.y(), box.hi.y()));
  return (nearest - centre).squaredNorm() < radius * radius;
}

bool polygonHitsBox(const std::vector<Vec2>& vertices, const Aabb& box) {
  const std::size_t n = vertices.size();
  if (n == 0) return false;
  for (const Vec2& v : vertices) {
    if (box.contains(v)) return true;
  }
  // A box corner inside the polygon: on the same side of every edge (either winding).
  const Vec2 corner = box.lo;
  int sign = 0;
  bool inside = true;
  for (std::size_t i = 0; i < n && inside; ++i) {
    const Vec2 e = vertices[(i + 1) % n] - vertices[i], r = corner - vertices[i];
    const double cross = e.x() * r.y() - e.y() * r.x();
    const int s = cross > 0 ? 1 : cross < 0 ? -1 : 0;
    if (s != 0 && sign != 0 && s != sign) inside = false;
    if (s != 0) sign = s;
  }
  if (inside) return true;
  for (std::size_t i = 0; i < n; ++i) {
    if (segmentHitsBox(vertices[i], vertices[(i + 1) % n], box)) return true;
  }
  return false;
}

double LabelSpace::cost(const Aabb& box) const {
  double total = 0.0;
  if (box.lo.x() < image_.lo.x() || box.lo.y() < image_.lo.y() || box.hi.x() > image_.hi.x() ||
      box.hi.y() > image_.hi.y()) {
    total += kOffImage;
  }
  for (const Box& b : boxes_) total += boxesOverlap(box, b.box) ? b.weight : 0.0;
  for (const Segment& s : segments_) total += segmentHitsBox(s.a, s.b, box) ? s.weight : 0.0;
  for (const Circle& c : discs_) total += discHitsBox(c.centre, c.radius, box) ? c.weight : 0.0;
  for (const ConvexPolygon& p : polygons_)
    total += polygonHitsBox(p.vertices, box) ? p.weight : 0.0;
  return total;
}

std::size_t LabelSpace::best(const std::vector<Aabb>& candidates) const {
  std::size_t chosen = 0;
  double lowest = HUGE_VAL;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const double c = cost(candidates[i]);
    if (c < lowest) {
      lowest = c;
      chosen = i;
    }
    if (c == 0.0) break;  // the first clear one
  }
  return chosen;
}

}  // namespace canopy::render::internal
