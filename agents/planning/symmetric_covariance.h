#pragma once
// The NBO cost's covariance recursion on the ten unique entries of a symmetric 4x4 P over
// ξ = (px, py, vx, vy): the NCV prediction and the Kalman update by a position measurement.
// Each entry is computed with the same operations, in the same order, as the full-matrix form
// (P⁻ = F P Fᵀ + Q; P ← P − c0 c0ᵀ/d0 − g gᵀ/d1), so the two agree bit for bit on a symmetric P;
// only the mirrored half is not recomputed (tests/agents/planning/symmetric_covariance_test.cpp).
#include <cstddef>
#include <cstring>
#include <type_traits>

#include "core/types.h"

namespace canopy::agents::planning {

/// Upper triangle of P, row by row: (00, 01, 02, 03, 11, 12, 13, 22, 23, 33). Units: m² on the
/// position block, m²/s across, m²/s² on the velocity block.
struct SymmetricCov4 {
  double p00, p01, p02, p03, p11, p12, p13, p22, p23, p33;

  /// The upper triangle of P (P assumed symmetric).
  static SymmetricCov4 fromUpper(const Mat4& P) {
    return {P(0, 0), P(0, 1), P(0, 2), P(0, 3), P(1, 1),
            P(1, 2), P(1, 3), P(2, 2), P(2, 3), P(3, 3)};
  }
  Mat4 full() const {
    Mat4 P;
    P << p00, p01, p02, p03,  //
        p01, p11, p12, p13,   //
        p02, p12, p22, p23,   //
        p03, p13, p23, p33;
    return P;
  }
  double positionTrace() const { return p00 + p11; }      // tr(P_pos), m²
  double trace() const { return p00 + p11 + p22 + p33; }  // tr(P), mixed units
};
// updatePosition reads and writes neighbouring entries in pairs.
static_assert(std::is_standard_layout_v<SymmetricCov4> &&
              sizeof(SymmetricCov4) == 10 * sizeof(double));

/// The NCV process noise Q(τ) by its three distinct values (each 2x2 block is a multiple of I).
struct NcvNoise {
  double pp = 0.0;  // m², σ_a² τ⁴/4
  double pv = 0.0;  // m²/s, σ_a² τ³/2
  double vv = 0.0;  // m²/s², σ_a² τ²

  /// Read from the full Q(τ) of agents/tracking/motion_model.h (the formula's one source).
  static NcvNoise of(const Mat4& Q) { return {Q(0, 0), Q(0, 2), Q(2, 2)}; }
};

/// P⁻ = F P Fᵀ + Q with F = [[I, τ I], [0, I]], by 2x2 blocks [[A, B], [Bᵀ, C]]:
///   A ← A + τ(B + Bᵀ) + τ² C + Q_pp,  B ← B + τ C + Q_pv,  C ← C + Q_vv.
/// B is not symmetric: B = [[p02, p03], [p12, p13]]. Cov: SymmetricCov4, or any struct with its
/// ten entries by the same names whose entries take + and · by a double (covariance_lanes.h).
template <class Cov>
inline void predictCovariance(Cov& P, double tau, const NcvNoise& Q) {
  const double tau2 = tau * tau;
  P.p00 = (P.p00 + (tau * (P.p02 + P.p02) + tau2 * P.p22)) + Q.pp;
  P.p01 = P.p01 + (tau * (P.p03 + P.p12) + tau2 * P.p23);  // Q_pp is diagonal
  P.p11 = (P.p11 + (tau * (P.p13 + P.p13) + tau2 * P.p33)) + Q.pp;
  P.p02 = (P.p02 + tau * P.p22) + Q.pv;
  P.p03 = P.p03 + tau * P.p23;  // Q_pv is diagonal too
  P.p12 = P.p12 + tau * P.p23;
  P.p13 = (P.p13 + tau * P.p33) + Q.pv;
  P.p22 += Q.vv;
  P.p33 += Q.vv;
}

/// One position measurement z = H ξ + v, v ~ N(0, R), H = [I 0], in Kalman form:
/// P ← P − C S⁻¹ Cᵀ, C = P Hᵀ = [c0 c1] (the first two columns), S = H P Hᵀ + R solved by its
/// LDLᵀ factors S = L D Lᵀ, L = [[1, 0], [l, 1]], D = diag(d0, d1):
///   C S⁻¹ Cᵀ = c0 c0ᵀ/d0 + g gᵀ/d1,  g = c1 − l c0,
/// two rank-one downdates of outer products, so P stays exactly symmetric.
inline void updatePosition(SymmetricCov4& P, const Mat2& R) {
  const double c0[4] = {P.p00, P.p01, P.p02, P.p03};          // P(:, 0)
  const double c1[4] = {P.p01, P.p11, P.p12, P.p13};          // P(:, 1)
  const double d0 = P.p00 + R(0, 0);                          // S₀₀
  const double l = (P.p01 + R(1, 0)) / d0;                    // S₁₀ / d0
  const double d1 = P.p11 + R(1, 1) - l * (P.p01 + R(0, 1));  // S₁₁ − l S₀₁
  const double g[4] = {c1[0] - l * c0[0], c1[1] - l * c0[1], c1[2] - l * c0[2],
                       c1[3] - l * c0[3]};  // c1 − l c0
  const double i0 = 1.0 / d0, i1 = 1.0 / d1;
  // P(r, c) −= c0_r c0_c / d0 + g_r g_c / d1 on r ≤ c, two neighbouring entries of the struct at
  // a time (each lane the scalar operations in the same order, so the same bits): the scalar
  // form was 7 instructions per entry, a third of a cost evaluation.
  using Pair = double __attribute__((vector_size(16)));
  unsigned char* bytes = reinterpret_cast<unsigned char*>(&P);
  auto downdate = [&](std::size_t offset, int r0, int k0, int r1, int k1) {
    Pair entry;
    std::memcpy(&entry, bytes + offset, sizeof entry);
    const Pair cr = {c0[r0], c0[r1]}, ck = {c0[k0], c0[k1]};
    const Pair gr = {g[r0], g[r1]}, gk = {g[k0], g[k1]};
    entry -= (cr * ck) * i0 + (gr * gk) * i1;
    std::memcpy(bytes + offset, &entry, sizeof entry);
  };
  downdate(offsetof(SymmetricCov4, p00), 0, 0, 0, 1);  // p00, p01
  downdate(offsetof(SymmetricCov4, p02), 0, 2, 0, 3);  // p02, p03
  downdate(offsetof(SymmetricCov4, p11), 1, 1, 1, 2);  // p11, p12
  downdate(offsetof(SymmetricCov4, p13), 1, 3, 2, 2);  // p13, p22
  downdate(offsetof(SymmetricCov4, p23), 2, 3, 3, 3);  // p23, p33
}

}  // namespace canopy::agents::planning
