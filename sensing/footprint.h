#pragma once
// Camera footprints φ_i: the ground area a downward camera sees (algorithms.md §3), or the sector a
// ground robot's forward camera sees, or the convex quadrilateral a pitched pinhole camera sees
// (sensing/camera.h).
#include <array>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/types.h"

namespace canopy::sensing {

enum class FootprintShape {
  rectangle,  // a downward camera: centred under the UAV, w along ψ
  disc,       // a downward camera: centred under the UAV
  sector,     // a forward camera at ground level: apex at the robot, opening about ψ
  quad,       // a pinhole camera pitched forward: a convex quadrilateral (a trapezoid) ahead of ψ
};

/// A quadrilateral footprint's corners relative to the agent's ground point, in its frame (x along
/// the heading ψ, y to its left), counter-clockwise.
using QuadCorners = std::array<Vec2, 4>;

/// The z-component of a × b.
inline double cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }
/// The area of a simple quadrilateral (m²), by the shoelace formula.
double quadArea(const QuadCorners& corners);

/// The camera's footprint relative to the agent (heterogeneous per agent).
struct FootprintDef {
  FootprintShape shape = FootprintShape::rectangle;
  Vec2 size = Vec2(20.0, 20.0);  // m, rectangle [w, h]: w along the heading ψ, h across
  double radius = 10.0;          // m, disc; for a sector its range
  double angle =
      0.5 * std::numbers::pi;  // rad, sector only: the field of view's full angle (0, 2π]
  QuadCorners corners{Vec2::Zero(), Vec2::Zero(), Vec2::Zero(), Vec2::Zero()};  // m, quad only
};

/// The largest distance from the agent's ground point to a point of its footprint (m).
inline double circumradius(const FootprintDef& def) {
  if (def.shape == FootprintShape::quad) {
    double r = 0.0;
    for (const Vec2& c : def.corners) r = std::max(r, c.norm());
    return r;
  }
  return def.shape == FootprintShape::rectangle ? 0.5 * def.size.norm() : def.radius;
}

/// A footprint placed on the ground: centred under the UAV (a sector: its apex at the robot) and
/// rotated by its yaw. A closed set.
struct Footprint {
  FootprintShape shape = FootprintShape::rectangle;
  Vec2 centre = Vec2::Zero();                   // m; a sector's apex
  double cos_yaw = 1.0;                         // cos ψ
  double sin_yaw = 0.0;                         // sin ψ
  Vec2 half = Vec2(10.0, 10.0);                 // m, rectangle half-extents
  double radius = 10.0;                         // m, disc; a sector's range
  double half_angle = 0.25 * std::numbers::pi;  // rad, sector: half the field of view, θ/2
  double cos_half = 0.5 * std::numbers::sqrt2;  // cos(θ/2), sector
  QuadCorners corners{Vec2::Zero(), Vec2::Zero(), Vec2::Zero(), Vec2::Zero()};  // quad, as the def

  static Footprint place(const FootprintDef& def, const Vec2& centre, double yaw);

  /// True when p lies in the closed footprint (1 nm of slack absorbs rotation rounding).
  bool contains(const Vec2& p) const { return containsFrom(centre, cos_yaw, sin_yaw, p); }
  /// contains(p) of this footprint moved to `at` with heading (cos ψ, sin ψ) = (c, s): for the
  /// planner, which places one footprint at many poses.
  bool containsFrom(const Vec2& at, double c, double s, const Vec2& p) const;
  /// The smallest axis-aligned box holding the footprint.
  Aabb bounds() const;
  double area() const;  // m²
  /// Maps (u, v) uniform on [0,1)² to a point uniform over the footprint.
  Vec2 pointFromUnitSquare(double u, double v) const;
  /// Sector: the point of its arc at angle `offset` (rad) from the heading.
  Vec2 sectorPoint(double offset) const;
  /// Quad: corner c (0..3) placed on the ground (m).
  Vec2 quadCorner(int c) const {
    const Vec2& q = corners[static_cast<std::size_t>(c)];
    return centre + Vec2(cos_yaw * q.x() - sin_yaw * q.y(), sin_yaw * q.x() + cos_yaw * q.y());
  }
};

/// Tolerance of the closed-set test (m).
inline constexpr double kFootprintSlack = 1e-9;

// Inline: the planner's cost asks it for every target at every sample of every candidate plan.
inline bool Footprint::containsFrom(const Vec2& at, double c, double s, const Vec2& p) const {
  const Vec2 d = p - at;
  if (shape == FootprintShape::quad) {
    // Into the footprint's frame, then inside every edge of the counter-clockwise corners:
    // (c_{e+1} − c_e) × (q − c_e) ≥ −slack · |c_{e+1} − c_e|.
    const Vec2 q(c * d.x() + s * d.y(), -s * d.x() + c * d.y());
    for (std::size_t e = 0; e < 4; ++e) {
      const Vec2& a = corners[e];
      const Vec2 edge = corners[(e + 1) % 4] - a;
      const double cross = edge.x() * (q.y() - a.y()) - edge.y() * (q.x() - a.x());
      if (cross < -kFootprintSlack * edge.norm()) return false;
    }
    return true;
  }
  if (shape != FootprintShape::rectangle) {
    const double r = radius + kFootprintSlack;
    const double d2 = d.squaredNorm();
    if (d2 > r * r) return false;
    if (shape == FootprintShape::disc) return true;
    // Sector: the angle between d and the heading is at most θ/2, i.e. d·ĥ ≥ |d| cos(θ/2) (the
    // apex itself included); 1 nm of slack on the projection, as elsewhere.
    const double along = c * d.x() + s * d.y();
    return along + kFootprintSlack >= std::sqrt(d2) * cos_half;
  }
  // Into the footprint's frame: rotate d by −ψ.
  const double along = c * d.x() + s * d.y();
  const double across = -s * d.x() + c * d.y();
  return std::abs(along) <= half.x() + kFootprintSlack &&
         std::abs(across) <= half.y() + kFootprintSlack;
}

}  // namespace canopy::sensing
