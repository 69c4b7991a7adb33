#pragma once
// Random covariances for the covariance recursion's tests (symmetric_covariance_test.cpp,
// covariance_lanes_test.cpp).
#include "core/random.h"
#include "core/types.h"

namespace canopy::agents::planning::test_support {

/// A random symmetric positive definite P = A Aᵀ + 0.1 I with entries of A in [−2, 2).
inline Mat4 randomCovariance(RandomStream& rng) {
  Mat4 A;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) A(r, c) = rng.uniform(-2.0, 2.0);
  }
  return A * A.transpose() + 0.1 * Mat4::Identity();
}

/// A random positive definite R = B Bᵀ + 0.05 I with entries of B in [−1, 1).
inline Mat2 randomNoise(RandomStream& rng) {
  Mat2 B;
  B << rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1);
  return B * B.transpose() + 0.05 * Mat2::Identity();
}

}  // namespace canopy::agents::planning::test_support
