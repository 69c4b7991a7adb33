#include "sensing/noise.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/random.h"

namespace canopy::sensing {
namespace {

TEST(RangeBearingCovariance, EigenvaluesAreRangeAndBearingVariances) {
  const SensorQuality q{0.3, 2.0};
  const Vec2 p_i(1, 2);
  const Vec2 z = p_i + Vec2(6, 8);  // d = 10, bearing atan2(8, 6)
  const Mat2 R = rangeBearingCovariance(z, p_i, q);
  Eigen::SelfAdjointEigenSolver<Mat2> eig(R);
  // Ascending eigenvalues: 0.1·α·d = 0.3, then 0.1·π·α·d = 0.3π.
  EXPECT_NEAR(eig.eigenvalues()(0), 0.1 * 0.3 * 10, 1e-12);
  EXPECT_NEAR(eig.eigenvalues()(1), 0.1 * std::numbers::pi * 0.3 * 10, 1e-12);
  // The smaller (range) eigenvector lies along the bearing (0.6, 0.8).
  EXPECT_NEAR(std::abs(eig.eigenvectors().col(0).dot(Vec2(0.6, 0.8))), 1.0, 1e-12);
  EXPECT_NEAR(R(0, 1), R(1, 0), 0.0);
}

TEST(RangeBearingCovariance, RangeIsFlooredAtR0) {
  const SensorQuality q{0.5, 2.0};
  const Mat2 R = rangeBearingCovariance(Vec2(0.5, 0), Vec2(0, 0), q);  // |z − p| = 0.5 < r0
  // Bearing 0: R = diag(0.1·α·r0, 0.1·π·α·r0).
  EXPECT_NEAR(R(0, 0), 0.1 * 0.5 * 2.0, 1e-15);
  EXPECT_NEAR(R(1, 1), 0.1 * std::numbers::pi * 0.5 * 2.0, 1e-15);
  EXPECT_NEAR(R(0, 1), 0.0, 1e-15);
  // Directly below the UAV (bearing undefined): still d = r0 and positive definite.
  const Mat2 below = rangeBearingCovariance(Vec2(0, 0), Vec2(0, 0), q);
  EXPECT_NEAR(below.trace(), 0.1 * 0.5 * 2.0 * (1 + std::numbers::pi), 1e-15);
  EXPECT_GT(below.determinant(), 0.0);
}

TEST(RangeBearingCovariance, ScalesLinearlyWithAlphaAndRange) {
  const Mat2 a = rangeBearingCovariance(Vec2(0, 5), Vec2(0, 0), {0.2, 2.0});
  const Mat2 b = rangeBearingCovariance(Vec2(0, 10), Vec2(0, 0), {0.6, 2.0});
  EXPECT_TRUE(b.isApprox(a * 6.0, 1e-14));  // 3× α and 2× d
}

// The trig-free form equals the literal eq. 2 with ρ = atan2 and G(ρ) built from cos ρ, sin ρ.
TEST(RangeBearingCovariance, EqualsTheRotationFormWithAtan2) {
  RandomStream rng(12, "noise-test");
  for (int k = 0; k < 1000; ++k) {
    const Vec2 z(rng.uniform(-50, 50), rng.uniform(-50, 50));
    const Vec2 p_i(rng.uniform(-50, 50), rng.uniform(-50, 50));
    const SensorQuality q{rng.uniform(0.1, 1.0), rng.uniform(0.5, 5.0)};
    const Vec2 offset = z - p_i;
    const double d = std::max(q.r0, offset.norm());
    const double rho = std::atan2(offset.y(), offset.x());
    Mat2 G;
    G << std::cos(rho), -std::sin(rho), std::sin(rho), std::cos(rho);
    const Mat2 D = Vec2(q.alpha * 0.1 * d, q.alpha * 0.1 * std::numbers::pi * d).asDiagonal();
    const Mat2 expected = G * D * G.transpose();
    const Mat2 R = rangeBearingCovariance(z, p_i, q);
    EXPECT_LE((R - expected).cwiseAbs().maxCoeff(), 1e-14 * expected.norm()) << k;
    EXPECT_EQ(R(0, 1), R(1, 0));
  }
}

TEST(RangeBearingCovariance, DrawnNoiseHasCovarianceR) {
  const Mat2 R = rangeBearingCovariance(Vec2(-7, 3), Vec2(2, -1), {0.3, 2.0});
  RandomStream rng(11, "noise-test");
  const int n = 50000;
  // Whitened draws w = L⁻¹ v must be N(0, I): Σ |w|² ~ χ²(2n), mean 2n, variance 4n.
  const Eigen::LLT<Mat2> llt(R);
  Mat2 sample = Mat2::Zero();
  double chi2 = 0.0;
  for (int i = 0; i < n; ++i) {
    const Vec2 v = rng.gaussian(R);
    sample += v * v.transpose();
    chi2 += llt.matrixL().solve(v).squaredNorm();
  }
  sample /= n;
  EXPECT_NEAR(chi2, 2.0 * n, 5.0 * std::sqrt(4.0 * n));
  // Each entry of the sample covariance: standard error sqrt((R_ii R_jj + R_ij²) / n).
  for (int r = 0; r < 2; ++r) {
    for (int c = 0; c < 2; ++c) {
      const double se = std::sqrt((R(r, r) * R(c, c) + R(r, c) * R(r, c)) / n);
      EXPECT_NEAR(sample(r, c), R(r, c), 5 * se) << r << "," << c;
    }
  }
}

}  // namespace
}  // namespace canopy::sensing
