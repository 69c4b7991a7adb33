#include "sensing/footprint.h"

#include <cmath>
#include <numbers>

namespace canopy::sensing {

double quadArea(const QuadCorners& c) {
  // Shoelace: ½ Σ c_e × c_{e+1}.
  double twice = 0.0;
  for (std::size_t e = 0; e < 4; ++e) twice += cross2(c[e], c[(e + 1) % 4]);
  return 0.5 * std::abs(twice);
}

Footprint Footprint::place(const FootprintDef& def, const Vec2& centre, double yaw) {
  Footprint f;
  f.shape = def.shape;
  f.centre = centre;
  f.cos_yaw = std::cos(yaw);
  f.sin_yaw = std::sin(yaw);
  f.half = 0.5 * def.size;
  f.radius = def.radius;
  f.half_angle = 0.5 * def.angle;
  f.cos_half = std::cos(f.half_angle);
  f.corners = def.corners;
  return f;
}

Vec2 Footprint::sectorPoint(double offset) const {
  // The heading rotated by `offset`: (cos(ψ + o), sin(ψ + o)) from cos ψ, sin ψ.
  const double c = std::cos(offset), s = std::sin(offset);
  return centre + radius * Vec2(cos_yaw * c - sin_yaw * s, sin_yaw * c + cos_yaw * s);
}

Aabb Footprint::bounds() const {
  if (shape == FootprintShape::sector) {
    // The apex, both ends of the arc, and each axis extreme centre ± r·e whose direction lies
    // within ±θ/2 of the heading.
    Aabb box{centre, centre};
    const auto grow = [&box](const Vec2& p) {
      box.lo = box.lo.cwiseMin(p);
      box.hi = box.hi.cwiseMax(p);
    };
    grow(sectorPoint(-half_angle));
    grow(sectorPoint(half_angle));
    const Vec2 axes[] = {Vec2(1, 0), Vec2(0, 1), Vec2(-1, 0), Vec2(0, -1)};
    for (const Vec2& e : axes) {
      if (cos_yaw * e.x() + sin_yaw * e.y() >= cos_half) grow(centre + radius * e);
    }
    return box;
  }
  if (shape == FootprintShape::quad) {
    Aabb box{quadCorner(0), quadCorner(0)};
    for (int c = 1; c < 4; ++c) {
      box.lo = box.lo.cwiseMin(quadCorner(c));
      box.hi = box.hi.cwiseMax(quadCorner(c));
    }
    return box;
  }
  Vec2 extent;
  if (shape == FootprintShape::disc) {
    extent = Vec2(radius, radius);
  } else {
    // Half-extents of a rotated box: |R| · half.
    const double c = std::abs(cos_yaw), s = std::abs(sin_yaw);
    extent = Vec2(c * half.x() + s * half.y(), s * half.x() + c * half.y());
  }
  return {centre - extent, centre + extent};
}

double Footprint::area() const {
  switch (shape) {
    case FootprintShape::disc:
      return std::numbers::pi * radius * radius;
    case FootprintShape::sector:
      return half_angle * radius * radius;  // ½ θ r²
    case FootprintShape::quad:
      return quadArea(corners);
    case FootprintShape::rectangle:
      break;
  }
  return 4.0 * half.x() * half.y();
}

Vec2 Footprint::pointFromUnitSquare(double u, double v) const {
  if (shape == FootprintShape::disc) {
    const double r = radius * std::sqrt(u);  // area-uniform radius
    const double theta = 2.0 * std::numbers::pi * v;
    return centre + Vec2(r * std::cos(theta), r * std::sin(theta));
  }
  if (shape == FootprintShape::sector) {
    const double r = std::sqrt(u);  // area-uniform fraction of the range
    return centre + r * (sectorPoint((2.0 * v - 1.0) * half_angle) - centre);
  }
  if (shape == FootprintShape::quad) {
    // Two triangles (c0, c1, c2) and (c0, c2, c3), chosen by u in proportion to their areas; in
    // the chosen one, a + √u'·((1 − v)(b − a) + v(c − a)) is area-uniform.
    const Vec2 a = quadCorner(0), b = quadCorner(1), c = quadCorner(2), d = quadCorner(3);
    const double first = std::abs(cross2(b - a, c - a));
    const double second = std::abs(cross2(c - a, d - a));
    const double split = first + second > 0.0 ? first / (first + second) : 1.0;
    if (u < split) {
      const double r = std::sqrt(u / split);
      return a + r * ((1.0 - v) * (b - a) + v * (c - a));
    }
    const double r = std::sqrt((u - split) / (1.0 - split));
    return a + r * ((1.0 - v) * (c - a) + v * (d - a));
  }
  const double along = (2.0 * u - 1.0) * half.x();
  const double across = (2.0 * v - 1.0) * half.y();
  return centre + Vec2(cos_yaw * along - sin_yaw * across, sin_yaw * along + cos_yaw * across);
}

}  // namespace canopy::sensing
