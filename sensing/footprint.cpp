#include "sensing/footprint.h"

#include <cmath>
#include <numbers>

namespace canopy::sensing {

Footprint Footprint::place(const FootprintDef& def, const Vec2& centre, double yaw) {
  Footprint f;
  f.shape = def.shape;
  f.centre = centre;
  f.cos_yaw = std::cos(yaw);
  f.sin_yaw = std::sin(yaw);
  f.half = 0.5 * def.size;
  f.radius = def.radius;
  return f;
}

Aabb Footprint::bounds() const {
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
  return shape == FootprintShape::disc ? std::numbers::pi * radius * radius
                                       : 4.0 * half.x() * half.y();
}

Vec2 Footprint::pointFromUnitSquare(double u, double v) const {
  if (shape == FootprintShape::disc) {
    const double r = radius * std::sqrt(u);  // area-uniform radius
    const double theta = 2.0 * std::numbers::pi * v;
    return centre + Vec2(r * std::cos(theta), r * std::sin(theta));
  }
  const double along = (2.0 * u - 1.0) * half.x();
  const double across = (2.0 * v - 1.0) * half.y();
  return centre + Vec2(cos_yaw * along - sin_yaw * across, sin_yaw * along + cos_yaw * across);
}

}  // namespace canopy::sensing
