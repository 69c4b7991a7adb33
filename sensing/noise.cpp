#include "sensing/noise.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace canopy::sensing {

Mat2 rangeBearingCovariance(const Vec2& z, const Vec2& p_i, const SensorQuality& quality) {
  const Vec2 offset = z - p_i;
  const double d = std::max(quality.r0, offset.norm());   // d = max(r0, |z − p_i|)
  const double rho = std::atan2(offset.y(), offset.x());  // bearing ρ
  const double c = std::cos(rho), s = std::sin(rho);
  const double range_var = quality.alpha * 0.1 * d;                       // α · 0.1 d
  const double bearing_var = quality.alpha * 0.1 * std::numbers::pi * d;  // α · 0.1 π d
  // G diag(a, b) Gᵀ with G = [[c, −s], [s, c]].
  Mat2 R;
  R(0, 0) = c * c * range_var + s * s * bearing_var;
  R(1, 1) = s * s * range_var + c * c * bearing_var;
  R(0, 1) = R(1, 0) = c * s * (range_var - bearing_var);
  return R;
}

}  // namespace canopy::sensing
