#pragma once
// Fixed-size Eigen types shared by every library. Units are SI (m, s, rad) throughout.
#include <Eigen/Core>

namespace canopy {

using Vec2 = Eigen::Vector2d;               // position or velocity in the plane (m, m/s)
using Mat2 = Eigen::Matrix2d;               // 2x2 covariance (m²)
using Vec4 = Eigen::Matrix<double, 4, 1>;   // target state ξ = (px, py, vx, vy)
using Mat4 = Eigen::Matrix<double, 4, 4>;   // 4x4 state covariance
using Mat24 = Eigen::Matrix<double, 2, 4>;  // H_obs = [I₂ 0]
using Mat42 = Eigen::Matrix<double, 4, 2>;  // Kalman gain

/// Axis-aligned box [lo, hi] (m).
struct Aabb {
  Vec2 lo = Vec2::Zero();
  Vec2 hi = Vec2::Zero();

  bool contains(const Vec2& p) const {
    return p.x() >= lo.x() && p.x() <= hi.x() && p.y() >= lo.y() && p.y() <= hi.y();
  }
  double width() const { return hi.x() - lo.x(); }
  double height() const { return hi.y() - lo.y(); }
  double area() const { return width() * height(); }
};

}  // namespace canopy
