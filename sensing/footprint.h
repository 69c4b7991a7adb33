#pragma once
// Camera footprints φ_i: the ground area a downward camera sees (algorithms.md §3).
#include <cmath>

#include "core/types.h"

namespace canopy::sensing {

enum class FootprintShape { rectangle, disc };

/// The camera's footprint relative to the UAV (heterogeneous per UAV).
struct FootprintDef {
  FootprintShape shape = FootprintShape::rectangle;
  Vec2 size = Vec2(20.0, 20.0);  // m, rectangle [w, h]: w along the heading ψ, h across
  double radius = 10.0;          // m, disc only
};

/// A footprint placed on the ground: centred under the UAV and rotated by its yaw. A closed set.
struct Footprint {
  FootprintShape shape = FootprintShape::rectangle;
  Vec2 centre = Vec2::Zero();    // m
  double cos_yaw = 1.0;          // cos ψ
  double sin_yaw = 0.0;          // sin ψ
  Vec2 half = Vec2(10.0, 10.0);  // m, rectangle half-extents
  double radius = 10.0;          // m, disc

  static Footprint place(const FootprintDef& def, const Vec2& centre, double yaw);

  /// True when p lies in the closed footprint (1 nm of slack absorbs rotation rounding).
  bool contains(const Vec2& p) const;
  /// The smallest axis-aligned box holding the footprint.
  Aabb bounds() const;
  double area() const;  // m²
  /// Maps (u, v) uniform on [0,1)² to a point uniform over the footprint.
  Vec2 pointFromUnitSquare(double u, double v) const;
};

/// Tolerance of the closed-set test (m).
inline constexpr double kFootprintSlack = 1e-9;

// Inline: the planner's cost asks it for every target at every sample of every candidate plan.
inline bool Footprint::contains(const Vec2& p) const {
  const Vec2 d = p - centre;
  if (shape == FootprintShape::disc) {
    const double r = radius + kFootprintSlack;
    return d.squaredNorm() <= r * r;
  }
  // Into the footprint's frame: rotate d by −ψ.
  const double along = cos_yaw * d.x() + sin_yaw * d.y();
  const double across = -sin_yaw * d.x() + cos_yaw * d.y();
  return std::abs(along) <= half.x() + kFootprintSlack &&
         std::abs(across) <= half.y() + kFootprintSlack;
}

}  // namespace canopy::sensing
