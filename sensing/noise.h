#pragma once
// The range-bearing measurement noise of the paper's eq. 2.
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
Mat2 rangeBearingCovariance(const Vec2& z, const Vec2& p_i, const SensorQuality& quality);

}  // namespace canopy::sensing
