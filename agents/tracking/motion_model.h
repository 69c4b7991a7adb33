#pragma once
// Motion models (algorithms.md §4, paper eq. 4): nearly constant velocity (NCV) for targets on
// ξ = (px, py, vx, vy), and the static model for trees on (cx, cy, r).
#include "agents/gaussian.h"
#include "core/types.h"

namespace canopy::agents::tracking {

/// NCV transition over τ seconds: per axis F(τ) = [[1, τ], [0, 1]] (4x4, dimensionless and s).
Mat4 ncvTransition(double tau);

/// NCV process noise, the discrete white-noise acceleration model (Bar-Shalom, Li & Kirubarajan
/// 2001, ch. 6): per axis Q(τ) = σ_a² [[τ⁴/4, τ³/2], [τ³/2, τ²]] (4x4: m², m²/s, m²/s²).
/// tau in s, sigma_a in m/s².
Mat4 ncvProcessNoise(double tau, double sigma_a);

/// NCV prediction: x̄ = F x, P̄ = F P Fᵀ + Q, symmetrised. tau in s, sigma_a in m/s².
TargetGaussian predictNcv(const TargetGaussian& posterior, double tau, double sigma_a);

/// Static model for trees (paper §III-A): F = I, Q = 0, so the prediction is the posterior.
inline TreeGaussian predictStatic(const TreeGaussian& posterior) {
  return posterior;
}

}  // namespace canopy::agents::tracking
