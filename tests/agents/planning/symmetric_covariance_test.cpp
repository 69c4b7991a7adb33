#include "agents/planning/symmetric_covariance.h"

#include <gtest/gtest.h>

#include <Eigen/LU>

#include "agents/tracking/motion_model.h"
#include "core/random.h"
#include "tests/agents/planning/random_covariance.h"

namespace canopy::agents::planning {
namespace {

using test_support::randomCovariance;
using test_support::randomNoise;

TEST(SymmetricCov4, RoundTripsTheUpperTriangle) {
  RandomStream rng(3, "symmetric-test");
  const Mat4 P = randomCovariance(rng);
  EXPECT_EQ(SymmetricCov4::fromUpper(P).full(), P);
  EXPECT_EQ(SymmetricCov4::fromUpper(P).positionTrace(), P(0, 0) + P(1, 1));
  EXPECT_DOUBLE_EQ(SymmetricCov4::fromUpper(P).trace(), P.trace());
}

// The prediction on the unique entries equals the full product F P Fᵀ + Q(τ).
TEST(SymmetricCov4, PredictionEqualsTheFullEigenProduct) {
  RandomStream rng(4, "symmetric-test");
  for (int trial = 0; trial < 200; ++trial) {
    const double tau = rng.uniform(0.05, 2.0), sigma_a = rng.uniform(0.1, 3.0);
    const Mat4 P = randomCovariance(rng);
    const Mat4 F = tracking::ncvTransition(tau);
    const Mat4 Q = tracking::ncvProcessNoise(tau, sigma_a);
    const Mat4 expected = F * P * F.transpose() + Q;
    SymmetricCov4 S = SymmetricCov4::fromUpper(P);
    predictCovariance(S, tau, NcvNoise::of(Q));
    EXPECT_LE((S.full() - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.norm()) << trial;
  }
}

// The Kalman downdate on the unique entries equals the information form
// (P⁻¹ + Hᵀ R⁻¹ H)⁻¹, H = [I 0], computed with full Eigen inverses.
TEST(SymmetricCov4, PositionUpdateEqualsTheInformationForm) {
  RandomStream rng(5, "symmetric-test");
  Mat24 H = Mat24::Zero();
  H(0, 0) = H(1, 1) = 1.0;
  for (int trial = 0; trial < 200; ++trial) {
    const Mat4 P = randomCovariance(rng);
    const Mat2 R = randomNoise(rng);
    const Mat4 expected = (P.inverse() + H.transpose() * R.inverse() * H).inverse();
    SymmetricCov4 S = SymmetricCov4::fromUpper(P);
    updatePosition(S, R);
    EXPECT_LE((S.full() - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.norm()) << trial;
  }
}

// And it equals the full-matrix Kalman form bit for bit, entry by entry.
TEST(SymmetricCov4, PositionUpdateEqualsTheFullKalmanFormExactly) {
  RandomStream rng(6, "symmetric-test");
  for (int trial = 0; trial < 200; ++trial) {
    Mat4 P = randomCovariance(rng);
    const Mat2 R = randomNoise(rng);
    SymmetricCov4 S = SymmetricCov4::fromUpper(P);
    updatePosition(S, R);
    const Vec4 c0 = P.col(0), c1 = P.col(1);
    const double d0 = P(0, 0) + R(0, 0);
    const double l = (P(1, 0) + R(1, 0)) / d0;
    const double d1 = P(1, 1) + R(1, 1) - l * (P(0, 1) + R(0, 1));
    const Vec4 g = c1 - l * c0;
    P -= (c0 * c0.transpose()) * (1.0 / d0) + (g * g.transpose()) * (1.0 / d1);
    EXPECT_EQ(S.full(), P) << trial;
  }
}

}  // namespace
}  // namespace canopy::agents::planning
