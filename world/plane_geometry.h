#pragma once
// Small plane geometry shared by the wall outlines (tree.cpp) and their convex pieces
// (convex_pieces.cpp).
#include <algorithm>
#include <sstream>
#include <string>

#include "core/types.h"

namespace canopy::world::plane {

/// a × b, the z component of the cross product (m²): > 0 when b turns left of a.
inline double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

/// The distance from p to the segment a → b (m); a degenerate segment is its point.
inline double pointSegmentDistance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 e = b - a;
  const double length_sq = e.squaredNorm();
  const double s = length_sq > 0.0 ? std::clamp((p - a).dot(e) / length_sq, 0.0, 1.0) : 0.0;
  return (a + s * e - p).norm();
}

/// x with three significant digits, for messages.
inline std::string metres(double x) {
  std::ostringstream text;
  text.precision(3);
  text << x;
  return text.str();
}

}  // namespace canopy::world::plane
