#pragma once
// The Kalman measurement update for a sensor that measures the first M components of an
// N-dimensional state, H = [I_M 0]: targets measure the position of ξ = (px, py, vx, vy)
// (N = 4, M = 2); trees measure their whole state (cx, cy, r) (N = M = 3).
#include <optional>

#include "agents/gaussian.h"

namespace canopy::agents::tracking {

/// Joseph-form update (Bar-Shalom, Li & Kirubarajan 2001, ch. 5), symmetrised:
///   S = H P Hᵀ + R (M×M), K = P Hᵀ S⁻¹ by a Cholesky solve (N×M),
///   x⁺ = x + K (z − H x), P⁺ = (I − K H) P (I − K H)ᵀ + K R Kᵀ.
/// Returns nothing when S is not positive definite.
/// Instantiated for (N, M) = (4, 2) and (3, 3).
template <int N, int M>
std::optional<Gaussian<N>> kalmanUpdate(const Gaussian<N>& prior,
                                        const Eigen::Matrix<double, M, 1>& z,
                                        const Eigen::Matrix<double, M, M>& R);

}  // namespace canopy::agents::tracking
