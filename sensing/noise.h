#pragma once
// The range-bearing measurement noise of the paper's eq. 2. The one source of R(z, p): the
// sensor draws with it and the planner's cost (agents/planning/nominal_cost.cpp) predicts with it.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/types.h"

namespace canopy::sensing {

/// Per-UAV sensor quality.
struct SensorQuality {
  double alpha = 0.3;  // α_i, scales the whole covariance (dimensionless)
  double r0 = 2.0;     // m, floor of the range d
};

/// R(z, p_i) = α · G(ρ) · diag(0.1·d, 0.1·π·d) · G(ρ)ᵀ with d = max(r0, |z − p_i|), ρ the bearing
/// from the UAV's ground point p_i to z and G(ρ) the rotation by ρ (m²). The first eigenvector
/// lies along the bearing (range error), the second across it (bearing error).
///
/// Without trigonometry: cos ρ and sin ρ are the components of the unit bearing (z − p)/|z − p|;
/// ρ = 0 when z = p, as atan2(0, 0) gives. Inline: the planner's cost calls it in its inner loop.
inline Mat2 rangeBearingCovariance(const Vec2& z, const Vec2& p_i, const SensorQuality& quality) {
  const Vec2 offset = z - p_i;
  const double r = offset.norm();
  const double d = std::max(quality.r0, r);          // d = max(r0, |z − p_i|)
  const double c = r > 0.0 ? offset.x() / r : 1.0;   // cos ρ
  const double s = r > 0.0 ? offset.y() / r : 0.0;   // sin ρ
  const double range_var = quality.alpha * 0.1 * d;  // α · 0.1 d
  const double bearing_var = quality.alpha * 0.1 * std::numbers::pi * d;  // α · 0.1 π d
  // G diag(a, b) Gᵀ with G = [[c, −s], [s, c]].
  Mat2 R;
  R(0, 0) = c * c * range_var + s * s * bearing_var;
  R(1, 1) = s * s * range_var + c * c * bearing_var;
  R(0, 1) = R(1, 0) = c * s * (range_var - bearing_var);
  return R;
}

}  // namespace canopy::sensing
