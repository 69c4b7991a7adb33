#include "agents/planning/covariance_lanes.h"

#include <gtest/gtest.h>

#include "agents/tracking/motion_model.h"
#include "core/random.h"
#include "tests/agents/planning/random_covariance.h"

namespace canopy::agents::planning {
namespace {

SymmetricCov4 randomCovariance(RandomStream& rng) {
  return SymmetricCov4::fromUpper(test_support::randomCovariance(rng));
}

// Positive definite, and not exactly symmetric in its last bits (as a fused R_fix may be), so
// that a lane that swapped R(0, 1) and R(1, 0) would show.
Mat2 randomNoise(RandomStream& rng) {
  Mat2 R = test_support::randomNoise(rng);
  R(1, 0) *= 1.0 + 1e-15;
  return R;
}

// Lane k holds P[k].
CovarianceLanes lanesOf(const SymmetricCov4 (&P)[4]) {
  CovarianceLanes c = CovarianceLanes::of(P[0]);
  for (int k = 1; k < 4; ++k) {
    c.p00[k] = P[k].p00, c.p01[k] = P[k].p01, c.p02[k] = P[k].p02, c.p03[k] = P[k].p03;
    c.p11[k] = P[k].p11, c.p12[k] = P[k].p12, c.p13[k] = P[k].p13;
    c.p22[k] = P[k].p22, c.p23[k] = P[k].p23, c.p33[k] = P[k].p33;
  }
  return c;
}

NoiseLanes lanesOf(const Mat2 (&R)[4]) {
  NoiseLanes n = NoiseLanes::of(R[0]);
  for (int k = 1; k < 4; ++k) {
    n.r00[k] = R[k](0, 0), n.r01[k] = R[k](0, 1), n.r10[k] = R[k](1, 0), n.r11[k] = R[k](1, 1);
  }
  return n;
}

void expectSameBits(const SymmetricCov4& a, const SymmetricCov4& b, int trial) {
  const double x[] = {a.p00, a.p01, a.p02, a.p03, a.p11, a.p12, a.p13, a.p22, a.p23, a.p33};
  const double y[] = {b.p00, b.p01, b.p02, b.p03, b.p11, b.p12, b.p13, b.p22, b.p23, b.p33};
  for (int k = 0; k < 10; ++k) EXPECT_EQ(x[k], y[k]) << "entry " << k << ", trial " << trial;
}

// Each lane of the four-lane prediction is the scalar prediction, bit for bit.
TEST(CovarianceLanes, PredictionIsTheScalarOneInEachLane) {
  RandomStream rng(11, "lanes-test");
  for (int trial = 0; trial < 200; ++trial) {
    const double tau = rng.uniform(0.05, 2.0), sigma_a = rng.uniform(0.1, 3.0);
    const NcvNoise Q = NcvNoise::of(tracking::ncvProcessNoise(tau, sigma_a));
    SymmetricCov4 P[4];
    for (SymmetricCov4& p : P) p = randomCovariance(rng);
    CovarianceLanes lanes = lanesOf(P);
    predictCovariance(lanes, tau, Q);
    for (int k = 0; k < 4; ++k) {
      predictCovariance(P[k], tau, Q);
      expectSameBits(lanes.lane(k), P[k], trial);
    }
  }
}

// A lane that sees is updated as the scalar update does it, bit for bit; a lane that does not
// keeps every bit of its P, whatever the other lanes do.
TEST(CovarianceLanes, UpdateIsTheScalarOneInTheLanesThatSee) {
  RandomStream rng(12, "lanes-test");
  for (int trial = 0; trial < 320; ++trial) {
    M4 seen;
    for (int k = 0; k < 4; ++k) seen[k] = (trial >> k & 1) != 0 ? -1 : 0;  // every mask, in turn
    SymmetricCov4 P[4];
    Mat2 R[4];
    for (int k = 0; k < 4; ++k) P[k] = randomCovariance(rng), R[k] = randomNoise(rng);
    CovarianceLanes lanes = lanesOf(P);
    updatePosition(lanes, lanesOf(R), seen);
    for (int k = 0; k < 4; ++k) {
      if (seen[k] != 0) updatePosition(P[k], R[k]);
      expectSameBits(lanes.lane(k), P[k], trial);
    }
  }
}

TEST(CovarianceLanes, TracesAreTheScalarOnesPerLane) {
  RandomStream rng(13, "lanes-test");
  SymmetricCov4 P[4];
  for (SymmetricCov4& p : P) p = randomCovariance(rng);
  const CovarianceLanes lanes = lanesOf(P);
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(lanes.positionTrace()[k], P[k].positionTrace());
    EXPECT_EQ(lanes.trace()[k], P[k].trace());
  }
}

}  // namespace
}  // namespace canopy::agents::planning
