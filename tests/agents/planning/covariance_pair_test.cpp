#include "agents/planning/covariance_pair.h"

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

void expectSameBits(const SymmetricCov4& a, const SymmetricCov4& b, int trial) {
  const double x[] = {a.p00, a.p01, a.p02, a.p03, a.p11, a.p12, a.p13, a.p22, a.p23, a.p33};
  const double y[] = {b.p00, b.p01, b.p02, b.p03, b.p11, b.p12, b.p13, b.p22, b.p23, b.p33};
  for (int k = 0; k < 10; ++k) EXPECT_EQ(x[k], y[k]) << "entry " << k << ", trial " << trial;
}

// Each lane of the paired prediction is the scalar prediction, bit for bit.
TEST(CovariancePair, PredictionIsTheScalarOneInEachLane) {
  RandomStream rng(11, "pair-test");
  for (int trial = 0; trial < 200; ++trial) {
    const double tau = rng.uniform(0.05, 2.0), sigma_a = rng.uniform(0.1, 3.0);
    const NcvNoise Q = NcvNoise::of(tracking::ncvProcessNoise(tau, sigma_a));
    SymmetricCov4 a = randomCovariance(rng), b = randomCovariance(rng);
    CovariancePair pair = CovariancePair::of(a, b);
    predictCovariance(pair, tau, Q);
    predictCovariance(a, tau, Q);
    predictCovariance(b, tau, Q);
    expectSameBits(pair.lane(0), a, trial);
    expectSameBits(pair.lane(1), b, trial);
  }
}

// A lane that sees is updated as the scalar update does it, bit for bit; a lane that does not
// keeps every bit of its P, whatever the other lane does.
TEST(CovariancePair, UpdateIsTheScalarOneInTheLanesThatSee) {
  RandomStream rng(12, "pair-test");
  const LaneMask masks[] = {{-1, -1}, {-1, 0}, {0, -1}};
  for (int trial = 0; trial < 300; ++trial) {
    const LaneMask seen = masks[trial % 3];
    const SymmetricCov4 a = randomCovariance(rng), b = randomCovariance(rng);
    const Mat2 Ra = randomNoise(rng), Rb = randomNoise(rng);
    const NoisePair R = NoisePair::of(Ra, Rb);
    CovariancePair pair = CovariancePair::of(a, b);
    updatePosition(pair, R, seen);
    SymmetricCov4 a_after = a, b_after = b;
    if (seen[0] != 0) updatePosition(a_after, Ra);
    if (seen[1] != 0) updatePosition(b_after, Rb);
    expectSameBits(pair.lane(0), a_after, trial);
    expectSameBits(pair.lane(1), b_after, trial);
  }
}

TEST(CovariancePair, TracesAreTheScalarOnesPerLane) {
  RandomStream rng(13, "pair-test");
  const SymmetricCov4 a = randomCovariance(rng), b = randomCovariance(rng);
  const CovariancePair pair = CovariancePair::of(a, b);
  EXPECT_EQ(pair.positionTrace()[0], a.positionTrace());
  EXPECT_EQ(pair.positionTrace()[1], b.positionTrace());
  EXPECT_EQ(pair.trace()[0], a.trace());
  EXPECT_EQ(pair.trace()[1], b.trace());
}

}  // namespace
}  // namespace canopy::agents::planning
