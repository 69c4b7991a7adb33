#include "core/random.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace canopy {
namespace {

TEST(RandomStream, SameSeedPurposeAndIndexGiveSameSequence) {
  RandomStream a(7, "sensing", 2), b(7, "sensing", 2);
  for (int i = 0; i < 1000; ++i) EXPECT_EQ(a.nextU64(), b.nextU64());
}

// The stream's first words for (1, "pso", 0), computed by a separate Python transcription of
// SplitMix64 seeding and xoshiro256** (the generator's published definitions): the inlined
// generator must stay the same generator.
TEST(RandomStream, MatchesAnIndependentTranscriptionOfXoshiro256StarStar) {
  RandomStream rng(1, "pso", 0);
  EXPECT_EQ(rng.nextU64(), 0xdf18945accda1160ULL);
  EXPECT_EQ(rng.nextU64(), 0x047bb77274e8b5c0ULL);
  EXPECT_EQ(rng.nextU64(), 0xa65ba79dd01341c0ULL);
}

// A batch is the same numbers as one call each, in the same order, and the stream continues
// from where the batch left it.
TEST(RandomStream, FillUniformGivesTheSameNumbersAsSuccessiveCalls) {
  RandomStream one(9, "pso", 4), batch(9, "pso", 4);
  std::vector<double> drawn(1001);
  batch.fillUniform(drawn);
  for (const double u : drawn) EXPECT_EQ(u, one.uniform());
  EXPECT_EQ(batch.nextU64(), one.nextU64());
}

TEST(RandomStream, PurposeIndexAndSeedEachChangeTheSequence) {
  RandomStream base(7, "sensing", 2);
  RandomStream other_purpose(7, "pso", 2), other_index(7, "sensing", 3),
      other_seed(8, "sensing", 2);
  const std::uint64_t first = base.nextU64();
  EXPECT_NE(first, other_purpose.nextU64());
  EXPECT_NE(first, other_index.nextU64());
  EXPECT_NE(first, other_seed.nextU64());
}

TEST(RandomStream, UniformHasMeanHalfAndVarianceOneTwelfth) {
  RandomStream rng(1, "test");
  const int n = 200000;
  double sum = 0, sum2 = 0;
  for (int i = 0; i < n; ++i) {
    const double u = rng.uniform();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    sum += u;
    sum2 += u * u;
  }
  const double mean = sum / n, var = sum2 / n - mean * mean;
  // Standard error of the mean: sqrt(1/12 / n) = 6.5e-4; 5σ bound.
  EXPECT_NEAR(mean, 0.5, 5 * std::sqrt(1.0 / 12 / n));
  EXPECT_NEAR(var, 1.0 / 12, 0.002);
}

TEST(RandomStream, NormalHasZeroMeanUnitVarianceAndGaussianTails) {
  RandomStream rng(2, "test");
  const int n = 200000;
  double sum = 0, sum2 = 0;
  int beyond_two_sigma = 0;
  for (int i = 0; i < n; ++i) {
    const double x = rng.normal();
    sum += x;
    sum2 += x * x;
    beyond_two_sigma += std::abs(x) > 2.0;
  }
  EXPECT_NEAR(sum / n, 0.0, 5 / std::sqrt(n));
  EXPECT_NEAR(sum2 / n, 1.0, 5 * std::sqrt(2.0 / n));
  // P(|X| > 2) = erfc(2/√2) = 0.0455; binomial standard error sqrt(p(1−p)/n).
  const double p = std::erfc(2.0 / std::sqrt(2.0));
  EXPECT_NEAR(static_cast<double>(beyond_two_sigma) / n, p, 5 * std::sqrt(p * (1 - p) / n));
}

TEST(RandomStream, PoissonMeanAndVarianceEqualTheRate) {
  for (const double mean : {0.3, 4.0, 50.0}) {
    RandomStream rng(3, "test", static_cast<std::uint64_t>(mean * 10));
    const int n = 20000;
    double sum = 0, sum2 = 0;
    for (int i = 0; i < n; ++i) {
      const double k = rng.poisson(mean);
      sum += k;
      sum2 += k * k;
    }
    const double m = sum / n, var = sum2 / n - m * m;
    EXPECT_NEAR(m, mean, 5 * std::sqrt(mean / n)) << mean;
    EXPECT_NEAR(var, mean, 0.05 * mean + 0.02) << mean;
  }
  RandomStream rng(3, "test");
  EXPECT_EQ(rng.poisson(0.0), 0);
  EXPECT_EQ(rng.poisson(-1.0), 0);
}

TEST(RandomStream, GaussianHandlesASingularCovariance) {
  RandomStream rng(4, "test");
  Mat2 degenerate;
  degenerate << 1.0, 0.0, 0.0, 0.0;  // all variance along x
  for (int i = 0; i < 100; ++i) EXPECT_EQ(rng.gaussian(degenerate).y(), 0.0);
  EXPECT_EQ(rng.gaussian(Mat2::Zero()), Vec2::Zero());
}

TEST(Fnv1a64, MatchesPublishedTestVectors) {
  // FNV-1a 64-bit reference values (Fowler/Noll/Vo test suite).
  EXPECT_EQ(fnv1a64(""), 0xcbf29ce484222325ULL);
  EXPECT_EQ(fnv1a64("a"), 0xaf63dc4c8601ec8cULL);
  EXPECT_EQ(fnv1a64("foobar"), 0x85944171f73967e8ULL);
}

}  // namespace
}  // namespace canopy
