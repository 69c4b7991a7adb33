#pragma once
// Four covariance recursions side by side: each of the ten unique entries of P holds one
// recursion per lane of a four-double vector (core/lanes.h), so one instruction advances four.
// The NBO cost runs the particles of the swarm four at a time this way, a track at a time
// (agents/planning/nominal_cost_evaluate.cpp). Each lane performs the scalar operations of
// symmetric_covariance.h in the same order, so a lane's bits are those of the scalar recursion
// (tests/agents/planning/covariance_lanes_test.cpp). The prediction is symmetric_covariance.h's
// template itself; the update below repeats the scalar update's operations on whole lanes, with a
// mask.
#include "agents/planning/symmetric_covariance.h"
#include "core/lanes.h"

namespace canopy::agents::planning {

using lanes::M4;
using lanes::V4;

/// The upper triangle of four covariances, entry by entry (units as SymmetricCov4).
struct CovarianceLanes {
  V4 p00, p01, p02, p03, p11, p12, p13, p22, p23, p33;

  /// P in every lane.
  [[gnu::always_inline]] static CovarianceLanes of(const SymmetricCov4& P) {
    using lanes::broadcast;
    return {broadcast(P.p00), broadcast(P.p01), broadcast(P.p02), broadcast(P.p03),
            broadcast(P.p11), broadcast(P.p12), broadcast(P.p13), broadcast(P.p22),
            broadcast(P.p23), broadcast(P.p33)};
  }
  SymmetricCov4 lane(int k) const {
    return {p00[k], p01[k], p02[k], p03[k], p11[k], p12[k], p13[k], p22[k], p23[k], p33[k]};
  }
  // Always inlined, like every function here that returns a vector: the cost compiled for AVX2
  // and a copy compiled without would disagree on the registers a returned vector travels in.
  [[gnu::always_inline]] V4 positionTrace() const { return p00 + p11; }      // tr(P_pos), m²
  [[gnu::always_inline]] V4 trace() const { return p00 + p11 + p22 + p33; }  // tr(P), mixed units
};

/// R of one position measurement per lane (m²). R(0, 1) and R(1, 0) are kept apart, as the scalar
/// update reads them: a fused R_fix = (Σ R_i⁻¹)⁻¹ need not be symmetric in its last bits.
struct NoiseLanes {
  V4 r00, r01, r10, r11;

  /// R in every lane.
  [[gnu::always_inline]] static NoiseLanes of(const Mat2& R) {
    using lanes::broadcast;
    return {broadcast(R(0, 0)), broadcast(R(0, 1)), broadcast(R(1, 0)), broadcast(R(1, 1))};
  }
};

/// updatePosition of symmetric_covariance.h in the lanes where `seen` holds:
///   P ← P − c0 c0ᵀ/d0 − g gᵀ/d1,  d0 = S₀₀, l = S₁₀/d0, d1 = S₁₁ − l S₀₁, g = c1 − l c0.
/// A lane that does not see keeps its P exactly: its 1/d0 and 1/d1 are zeroed, so it subtracts
/// +0. Its R must still be positive definite (any will do) so that nothing there overflows.
[[gnu::always_inline]] inline void updatePosition(CovarianceLanes& P, const NoiseLanes& R,
                                                  M4 seen) {
  const V4 c0[4] = {P.p00, P.p01, P.p02, P.p03};      // P(:, 0)
  const V4 d0 = P.p00 + R.r00;                        // S₀₀
  const V4 l = (P.p01 + R.r10) / d0;                  // S₁₀ / d0
  const V4 d1 = P.p11 + R.r11 - l * (P.p01 + R.r01);  // S₁₁ − l S₀₁
  const V4 g[4] = {P.p01 - l * c0[0], P.p11 - l * c0[1], P.p12 - l * c0[2],
                   P.p13 - l * c0[3]};  // c1 − l c0, c1 = P(:, 1)
  const V4 i0 = (V4)((M4)(1.0 / d0) & seen);
  const V4 i1 = (V4)((M4)(1.0 / d1) & seen);
  // P(r, c) −= c0_r c0_c / d0 + g_r g_c / d1 on r ≤ c.
  auto downdate = [&](V4& entry, int r, int c) {
    entry -= (c0[r] * c0[c]) * i0 + (g[r] * g[c]) * i1;
  };
  downdate(P.p00, 0, 0);
  downdate(P.p01, 0, 1);
  downdate(P.p02, 0, 2);
  downdate(P.p03, 0, 3);
  downdate(P.p11, 1, 1);
  downdate(P.p12, 1, 2);
  downdate(P.p13, 1, 3);
  downdate(P.p22, 2, 2);
  downdate(P.p23, 2, 3);
  downdate(P.p33, 3, 3);
}

}  // namespace canopy::agents::planning
