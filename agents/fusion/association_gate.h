#pragma once
// The association's gate: the distance between two position estimates, and a bound that admits
// pairs without computing it, d² = Δpᵀ (S_a + S_b)⁻¹ Δp ≤ |Δp|² / (λ_a + λ_b), with λ the least
// eigenvalue of each covariance (Weyl: λ_min(S_a + S_b) ≥ λ_a + λ_b). The bound passes every pair
// of a key's copies that lie close to their common centre (TrackAssociation::linkByKey).
#include <cmath>
#include <limits>

#include "core/types.h"

namespace canopy::agents::fusion {

/// Squared Mahalanobis distance between two position estimates, d² = Δpᵀ (S_a + S_b)⁻¹ Δp
/// (Bar-Shalom, Willett & Tian 2011, track-to-track association, cross-covariance neglected).
/// ∞ when S_a + S_b is not positive definite. Symmetric in its two estimates, to the bit.
inline double mahalanobis2(const Vec2& pa, const Mat2& Sa, const Vec2& pb, const Mat2& Sb) {
  const Mat2 S = Sa + Sb;  // 2x2
  const double det = S(0, 0) * S(1, 1) - S(0, 1) * S(1, 0);
  if (!(S(0, 0) > 0.0) || !(det > 0.0)) {
    return std::numeric_limits<double>::infinity();  // not positive definite (or NaN)
  }
  const Vec2 d = pa - pb;
  // S⁻¹Δp by Cramer's rule, the 2x2 solve: [s11 −s01; −s10 s00] Δp / det.
  const Vec2 solved(S(1, 1) * d.x() - S(0, 1) * d.y(), S(0, 0) * d.y() - S(1, 0) * d.x());
  return d.dot(solved) / det;
}

/// A lower bound on the least eigenvalue of a 2×2 position covariance S (m²), or 0 when the bound
/// is not to be used: S not finite, not positive definite, asymmetric beyond rounding, or so
/// ill-conditioned (λ_max / λ_min beyond about 2000) that the gate's own arithmetic (the 2×2
/// determinant, exact to about 4 ε κ² relative) could disagree with the exact value.
///
/// For the symmetric part [a s; s c]: λ_min = (a + c)/2 − √(((a − c)/2)² + s²). An asymmetry δ only
/// lowers d² (det S = det S_sym + δ², the quadratic form sees S_sym), so it is allowed up to
/// rounding. The result is shaded by 10⁻⁶ against the rounding of this formula.
inline double eigenFloor(const Mat2& S) {
  const double a = S(0, 0);
  const double c = S(1, 1);
  const double s = 0.5 * (S(0, 1) + S(1, 0));
  const double half_trace = 0.5 * (a + c);
  if (!std::isfinite(half_trace) || !std::isfinite(s) || !(a > 0.0) || !(c > 0.0)) return 0.0;
  if (!(std::abs(S(0, 1) - S(1, 0)) <= 1e-9 * half_trace)) return 0.0;
  const double lambda = half_trace - std::hypot(0.5 * (a - c), s);
  if (!(lambda >= 1e-3 * half_trace)) return 0.0;  // κ = λ_max / λ_min ≤ about 2000
  return lambda * (1.0 - 1e-6);
}

/// Whether a copy at distance `reach` (m) from a centre, with eigenFloor `floor` (m²), lies in the
/// core: any two core copies (reaches r_a, r_b, floors λ_a, λ_b) then have
///   d² ≤ (r_a + r_b)² / (λ_a + λ_b) ≤ 2 (r_a² + r_b²) / (λ_a + λ_b) ≤ gate / 2,
/// since r² ≤ gate · λ / 4 for each. Half the gate is far more than the rounding of either side.
inline bool inGateCore(double reach, double floor, double gate) {
  return floor > 0.0 && reach * reach <= 0.25 * gate * floor;
}

}  // namespace canopy::agents::fusion
