#pragma once
// How an Observation enters a track's filter: the measured components z, their noise R, and the
// Gaussian a track is born with (algorithms.md §4). Targets measure the position of
// ξ = (px, py, vx, vy); trees measure their whole state (cx, cy, r). In both H = [I_M 0].
#include <algorithm>
#include <cmath>

#include "agents/config.h"
#include "agents/gaussian.h"
#include "sensing/observation.h"

namespace canopy::agents::tracking {

/// Floor of a tree's radius variance (m²): keeps S and P₀ positive definite when σ_r = 0.
inline constexpr double kMinRadiusVariance = 1e-6;

template <int N>
struct MeasurementModel;

/// Targets: z = (x, y) (m), R from the observation (m²), H = [I₂ 0].
template <>
struct MeasurementModel<4> {
  static constexpr int M = 2;
  static Vec2 z(const sensing::Observation& o) { return o.z; }
  static Mat2 R(const sensing::Observation& o) { return o.R; }
  /// x₀ = (z, 0, 0), P₀ = diag(R, σ_v² I₂) with σ_v = birth_velocity_sigma (m/s).
  static TargetGaussian birth(const sensing::Observation& o, const TrackingConfig& config) {
    TargetGaussian g;
    g.x << o.z, 0.0, 0.0;
    g.P.setZero();
    g.P.topLeftCorner<2, 2>() = o.R;
    g.P.bottomRightCorner<2, 2>().diagonal().setConstant(config.birth_velocity_sigma *
                                                         config.birth_velocity_sigma);
    return g;
  }
  /// A usable target observation: finite, R symmetric positive definite.
  static bool valid(const sensing::Observation& o) {
    return o.z.allFinite() && o.R.allFinite() && o.R(0, 0) > 0.0 &&
           o.R(0, 0) * o.R(1, 1) - o.R(0, 1) * o.R(1, 0) > 0.0;
  }
};

/// Trees: z = (cx, cy, r) (m), R₃ = blkdiag(R, σ_r²) (m²), H = I₃.
template <>
struct MeasurementModel<3> {
  static constexpr int M = 3;
  static Eigen::Vector3d z(const sensing::Observation& o) { return {o.z.x(), o.z.y(), o.radius}; }
  static Eigen::Matrix3d R(const sensing::Observation& o) {
    Eigen::Matrix3d R = Eigen::Matrix3d::Zero();
    R.topLeftCorner<2, 2>() = o.R;
    R(2, 2) = std::max(o.radius_variance, kMinRadiusVariance);
    return R;
  }
  /// x₀ = (z, max(r, r_min)), P₀ = blkdiag(R, σ_r²).
  static TreeGaussian birth(const sensing::Observation& o, const TrackingConfig& config) {
    TreeGaussian g;
    g.x = z(o);
    g.x(2) = std::max(g.x(2), config.tree_min_radius);
    g.P = R(o);
    return g;
  }
  static bool valid(const sensing::Observation& o) {
    return MeasurementModel<4>::valid(o) && std::isfinite(o.radius) &&
           std::isfinite(o.radius_variance);
  }
};

}  // namespace canopy::agents::tracking
