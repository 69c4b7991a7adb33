#pragma once
// Negative information: what a scan that saw nothing of a target says about where it is.
//
// A target track whose scan gave it no measurement keeps, in plain JPDA, its prediction: as if
// the camera had not looked. But a camera that looked at part of where the target could be and
// saw nothing says it is less likely there. With P_D the probability of detecting a visible
// target (times the gate's P_G: a detection outside the gate is a miss too), the position's
// density after the miss is (Koch 2007, "On exploiting 'negative' sensor evidence")
//   p(x | miss) ∝ N(x; x̂, P) · (1 − P_D · 1[x visible]),
// which this replaces by the Gaussian of the same first two moments. Only the position decides
// visibility, so the velocity follows its linear regression on the position,
//   v | p ~ N(v̂ + K (p − p̂), P_vv − K P_pv),  K = P_vp P_pp⁻¹,
// which gives the moment-matched posterior
//   p̂' = E[p],  P'_pp = Cov[p],  v̂' = v̂ + K (p̂' − p̂),
//   P'_vp = K P'_pp,  P'_vv = P_vv − K P_pv + K P'_pp Kᵀ.
// The position's moments split N(p̂, P_pp) into what the camera sees and what it does not: the
// whole has the moments (1, 0, I) in u = L⁻¹(p − p̂) (L Lᵀ = P_pp), so only the visible part's,
//   m_v = ∫ 1[visible] φ,  f_v = ∫ u 1[visible] φ,  S_v = ∫ u uᵀ 1[visible] φ,
// are approximated, on a midpoint grid of kCells² cells over ±kSpan σ. The footprint's edge is a
// step, and a cell it crosses counts whole: the error is the mass of half a cell's width along
// the edge (a square of ±1σ: m_v 0.551 for 0.466, the variance after 11 % high; a half plane
// through the mean: 1 %). Gauss–Hermite nodes of order 16, spaced widely away from the mean,
// did worse at a step (9 % on the half plane). Then
//   Z = 1 − P_D m_v,  E[u] = −P_D f_v / Z,  E[u uᵀ] = (I − P_D S_v) / Z,
// and p̂' = p̂ + L E[u], P'_pp = L Cov[u] Lᵀ. Nothing visible: the prior, exactly.
#include <array>
#include <functional>

#include "agents/gaussian.h"

namespace canopy::agents::tracking {

/// The grid: cell centres u_i = −kSpan + h (i + ½), h = 2 kSpan / kCells, per axis, and their
/// weights φ(u_i) normalised to sum to 1.
struct NormalGrid {
  static constexpr int kCells = 24;
  static constexpr double kSpan = 4.5;
  std::array<double, kCells> nodes{};
  std::array<double, kCells> weights{};
};
const NormalGrid& normalGrid();

/// The moment-matched Gaussian after a scan that gave the track no measurement, where
/// visible(p) says whether the own camera would have seen a target at p, and p_detect is the
/// P_D (× P_G) of a visible one. Returns the prior when P_pp is not positive definite or no node
/// is visible.
TargetGaussian afterMissedDetection(const TargetGaussian& prior, double p_detect,
                                    const std::function<bool(const Vec2&)>& visible);

}  // namespace canopy::agents::tracking
