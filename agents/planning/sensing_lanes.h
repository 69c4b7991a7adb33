#pragma once
// Sensing's footprint test (sensing/footprint.h, Footprint::containsFrom) and range-bearing noise
// (sensing/noise.h, rangeBearingCovariance) for four poses of one UAV at once, one per lane, as
// the NBO cost asks them for four particles of the swarm. Each lane performs the scalar
// function's operations in the same order, so it answers with the scalar function's bits
// (tests/agents/planning/sensing_lanes_test.cpp); the scalar functions stay the formulas' source.
#include <numbers>

#include "agents/planning/covariance_lanes.h"
#include "core/lanes.h"
#include "sensing/camera.h"
#include "sensing/footprint.h"
#include "sensing/noise.h"

namespace canopy::agents::planning {

/// Four poses of a UAV: ground points (x, y) in m and headings (cos ψ, sin ψ). Aligned to 32
/// bytes in every translation unit (outside an AVX one GCC aligns V4 to 16 only), so that the
/// AVX2 cost's aligned stores into NominalCost's vector of them hold (flyLanes).
struct alignas(32) PoseLanes {
  V4 x, y, c, s;
};

/// What the two tests below read of a UAV's footprint and sensor, in every lane, worked out once
/// per UAV (NominalCost::prepare) rather than at each of the cost's measurements: the same
/// scalar operations on the same values, so the same bits (tests/agents/planning/
/// sensing_lanes_test.cpp). A constant splat (a, a, a, a) is what `a * v` multiplies v by;
/// r0 is broadcast(r0) as the std::max below compares it.
struct alignas(32) SensorLanes {
  V4 half_x, half_y;              // m, a rectangle's half sides + kFootprintSlack
  V4 r0;                          // m, the range below which the noise is that of r0
  V4 range_scale, bearing_scale;  // α·0.1 and α·0.1·π (noise per metre of range)

  static SensorLanes of(const sensing::Footprint& at_origin, const sensing::SensorQuality& q) {
    auto splat = [](double a) { return V4{a, a, a, a}; };
    return {splat(at_origin.half.x() + sensing::kFootprintSlack),
            splat(at_origin.half.y() + sensing::kFootprintSlack), lanes::broadcast(q.r0),
            splat(q.alpha * 0.1), splat(q.alpha * 0.1 * std::numbers::pi)};
  }
};

/// Per lane: whether the offset (dx, dy) = z − (x, y) lies in the footprint placed at the
/// origin and turned by the lane's heading, as Footprint::containsFrom tests it (a rectangle's
/// half sides read from `sensor`, the other shapes' sizes from at_origin).
[[gnu::always_inline]] inline M4 footprintHoldsOffset(const sensing::Footprint& at_origin,
                                                      const SensorLanes& sensor,
                                                      const PoseLanes& pose, const V4& dx,
                                                      const V4& dy) {
  using sensing::kFootprintSlack;
  if (at_origin.shape == sensing::FootprintShape::rectangle) {  // the paper's camera: first
    const V4 along = pose.c * dx + pose.s * dy;
    const V4 across = -pose.s * dx + pose.c * dy;
    return (lanes::abs(along) <= sensor.half_x) & (lanes::abs(across) <= sensor.half_y);
  }
  if (at_origin.shape == sensing::FootprintShape::quad) {  // a pitched camera (issue 53)
    const V4 qx = pose.c * dx + pose.s * dy;
    const V4 qy = -pose.s * dx + pose.c * dy;
    M4 inside = M4{} - 1;
    for (std::size_t e = 0; e < 4; ++e) {
      const Vec2& a = at_origin.corners[e];
      const Vec2 edge = at_origin.corners[(e + 1) % 4] - a;
      const V4 cross = edge.x() * (qy - a.y()) - edge.y() * (qx - a.x());
      inside &= ~(cross < -kFootprintSlack * edge.norm());
    }
    return inside;
  }
  const double r = at_origin.radius + kFootprintSlack;
  const V4 d2 = dx * dx + dy * dy;
  const M4 within = ~(d2 > r * r);  // the scalar returns false when d2 > r² (so NaN is within)
  if (at_origin.shape == sensing::FootprintShape::disc) return within;
  const V4 along = pose.c * dx + pose.s * dy;
  return within & (along + kFootprintSlack >= lanes::sqrt(d2) * at_origin.cos_half);
}
[[gnu::always_inline]] inline M4 footprintHoldsOffset(const sensing::Footprint& at_origin,
                                                      const PoseLanes& pose, const V4& dx,
                                                      const V4& dy) {
  return footprintHoldsOffset(at_origin, SensorLanes::of(at_origin, {}), pose, dx, dy);
}

/// Per lane: at_origin.containsFrom((x, y), c, s, z).
[[gnu::always_inline]] inline M4 footprintHolds(const sensing::Footprint& at_origin,
                                                const SensorLanes& sensor, const PoseLanes& pose,
                                                const Vec2& z) {
  return footprintHoldsOffset(at_origin, sensor, pose, z.x() - pose.x, z.y() - pose.y);
}
[[gnu::always_inline]] inline M4 footprintHolds(const sensing::Footprint& at_origin,
                                                const PoseLanes& pose, const Vec2& z) {
  return footprintHolds(at_origin, SensorLanes::of(at_origin, {}), pose, z);
}

/// Per lane: whether the footprint scaled by 1/k about the lane's ground point holds z, i.e.
/// k·(z − p) lies in at_origin (height: the footprint at altitude h is the one at z0 scaled by
/// h/z0, so k = z0/h; the slack kFootprintSlack is then in the scaled frame).
[[gnu::always_inline]] inline M4 footprintHoldsScaled(const sensing::Footprint& at_origin,
                                                      const SensorLanes& sensor,
                                                      const PoseLanes& pose, const Vec2& z,
                                                      const V4& k) {
  return footprintHoldsOffset(at_origin, sensor, pose, (z.x() - pose.x) * k, (z.y() - pose.y) * k);
}
[[gnu::always_inline]] inline M4 footprintHoldsScaled(const sensing::Footprint& at_origin,
                                                      const PoseLanes& pose, const Vec2& z,
                                                      const V4& k) {
  return footprintHoldsScaled(at_origin, SensorLanes::of(at_origin, {}), pose, z, k);
}

/// Per lane: the slant factor ℓ(h)/ℓ(h_ref) of sensing::slantNoiseFactor,
/// √(|z − p|² + h²) / √(|z − p|² + h_ref²).
[[gnu::always_inline]] inline V4 slantFactor(const Vec2& z, const V4& x, const V4& y,
                                             const V4& h) {
  const V4 dx = z.x() - x, dy = z.y() - y;
  const V4 r2 = dx * dx + dy * dy;
  const double h_ref = sensing::kDefaultAltitude;
  return lanes::sqrt(r2 + h * h) / lanes::sqrt(r2 + h_ref * h_ref);
}

/// Per lane: R(z, p) of sensing::rangeBearingCovariance with p = (x, y), the quality's
/// constants read from `sensor` (SensorLanes::of(·, q)).
[[gnu::always_inline]] inline NoiseLanes rangeBearingCovariance(const Vec2& z, const V4& x,
                                                                const V4& y,
                                                                const SensorLanes& sensor) {
  const V4 dx = z.x() - x, dy = z.y() - y;
  const V4 r = lanes::sqrt(dx * dx + dy * dy);  // |z − p|
  const V4 d = sensor.r0 < r ? r : sensor.r0;   // std::max(r0, r)
  const M4 away = r > 0.0;
  const V4 c = away ? dx / r : lanes::broadcast(1.0);  // cos ρ
  const V4 s = away ? dy / r : V4{};                   // sin ρ
  const V4 range_var = sensor.range_scale * d;         // α · 0.1 d
  const V4 bearing_var = sensor.bearing_scale * d;     // α · 0.1 π d
  const V4 cs = c * s * (range_var - bearing_var);
  return {c * c * range_var + s * s * bearing_var, cs, cs, s * s * range_var + c * c * bearing_var};
}
[[gnu::always_inline]] inline NoiseLanes rangeBearingCovariance(const Vec2& z, const V4& x,
                                                                const V4& y,
                                                                const sensing::SensorQuality& q) {
  return rangeBearingCovariance(z, x, y, SensorLanes::of(sensing::Footprint{}, q));
}

}  // namespace canopy::agents::planning
