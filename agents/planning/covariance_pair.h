#pragma once
// Two tracks' covariance recursions side by side: each of the ten unique entries of P holds track
// a in the first lane of an SSE2 pair and track b in the second, so one instruction advances both.
// Each lane performs the scalar operations of symmetric_covariance.h in the same order, so a
// lane's bits are those of the scalar recursion (tests/agents/planning/covariance_pair_test.cpp).
// The NBO cost runs its tracks two at a time this way (agents/planning/nominal_cost.cpp): the
// scalar form spent most of its instructions moving entries in and out of pairs. The prediction
// is symmetric_covariance.h's template itself; the update below repeats the scalar update's
// operations on whole lanes, with a mask.
#include <cstdint>

#include "agents/planning/symmetric_covariance.h"

namespace canopy::agents::planning {

using Lanes = double __attribute__((vector_size(16)));           // (track a, track b)
using LaneMask = std::int64_t __attribute__((vector_size(16)));  // per lane: −1 true, 0 false

inline bool anyLane(LaneMask mask) {
  return (mask[0] | mask[1]) != 0;
}

/// The upper triangle of two covariances, entry by entry (units as SymmetricCov4).
struct CovariancePair {
  Lanes p00, p01, p02, p03, p11, p12, p13, p22, p23, p33;

  static CovariancePair of(const SymmetricCov4& a, const SymmetricCov4& b) {
    return {Lanes{a.p00, b.p00}, Lanes{a.p01, b.p01}, Lanes{a.p02, b.p02}, Lanes{a.p03, b.p03},
            Lanes{a.p11, b.p11}, Lanes{a.p12, b.p12}, Lanes{a.p13, b.p13}, Lanes{a.p22, b.p22},
            Lanes{a.p23, b.p23}, Lanes{a.p33, b.p33}};
  }
  SymmetricCov4 lane(int k) const {
    return {p00[k], p01[k], p02[k], p03[k], p11[k], p12[k], p13[k], p22[k], p23[k], p33[k]};
  }
  Lanes positionTrace() const { return p00 + p11; }      // tr(P_pos), m²
  Lanes trace() const { return p00 + p11 + p22 + p33; }  // tr(P), mixed units
};

/// R of one position measurement per lane (m²). R(0, 1) and R(1, 0) are kept apart, as the scalar
/// update reads them: a fused R_fix = (Σ R_i⁻¹)⁻¹ need not be symmetric in its last bits.
struct NoisePair {
  Lanes r00, r01, r10, r11;

  /// R_a in the first lane, R_b in the second.
  static NoisePair of(const Mat2& a, const Mat2& b) {
    return {Lanes{a(0, 0), b(0, 0)}, Lanes{a(0, 1), b(0, 1)}, Lanes{a(1, 0), b(1, 0)},
            Lanes{a(1, 1), b(1, 1)}};
  }
};

/// updatePosition of symmetric_covariance.h in the lanes where `seen` holds:
///   P ← P − c0 c0ᵀ/d0 − g gᵀ/d1,  d0 = S₀₀, l = S₁₀/d0, d1 = S₁₁ − l S₀₁, g = c1 − l c0.
/// A lane that does not see keeps its P exactly: its 1/d0 and 1/d1 are zeroed, so it subtracts
/// +0. Its R must still be positive definite (any will do) so that nothing there overflows.
inline void updatePosition(CovariancePair& P, const NoisePair& R, LaneMask seen) {
  const Lanes c0[4] = {P.p00, P.p01, P.p02, P.p03};      // P(:, 0)
  const Lanes d0 = P.p00 + R.r00;                        // S₀₀
  const Lanes l = (P.p01 + R.r10) / d0;                  // S₁₀ / d0
  const Lanes d1 = P.p11 + R.r11 - l * (P.p01 + R.r01);  // S₁₁ − l S₀₁
  const Lanes g[4] = {P.p01 - l * c0[0], P.p11 - l * c0[1], P.p12 - l * c0[2],
                      P.p13 - l * c0[3]};  // c1 − l c0, c1 = P(:, 1)
  const Lanes i0 = (Lanes)((LaneMask)(1.0 / d0) & seen);
  const Lanes i1 = (Lanes)((LaneMask)(1.0 / d1) & seen);
  // P(r, c) −= c0_r c0_c / d0 + g_r g_c / d1 on r ≤ c.
  auto downdate = [&](Lanes& entry, int r, int c) {
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
