#include "agents/tracking/kalman.h"

#include <gtest/gtest.h>

#include <Eigen/LU>

namespace canopy::agents::tracking {
namespace {

TEST(Kalman, UpdateMatchesHandComputationPerAxis) {
  // Axes decoupled; per axis the scalar Kalman update: S = P_pp + r, K = (P_pp, P_pv) / S.
  TargetGaussian prior;
  prior.x << 1.0, 2.0, 0.5, -0.5;
  prior.P.setZero();
  prior.P(0, 0) = 2.0;  // x axis: [[2, 1], [1, 2]]
  prior.P(0, 2) = prior.P(2, 0) = 1.0;
  prior.P(2, 2) = 2.0;
  prior.P(1, 1) = 3.0;  // y axis: [[3, 0.5], [0.5, 1]]
  prior.P(1, 3) = prior.P(3, 1) = 0.5;
  prior.P(3, 3) = 1.0;
  const Mat2 R = Vec2(1.0, 2.0).asDiagonal();
  const auto post = kalmanUpdate<4, 2>(prior, Vec2(2.0, 1.0), R);
  ASSERT_TRUE(post.has_value());
  // x: S = 3, K = (2/3, 1/3), ν = 1.  y: S = 5, K = (3/5, 1/10), ν = −1.
  EXPECT_NEAR(post->x(0), 5.0 / 3.0, 1e-14);
  EXPECT_NEAR(post->x(2), 5.0 / 6.0, 1e-14);
  EXPECT_NEAR(post->x(1), 1.4, 1e-14);
  EXPECT_NEAR(post->x(3), -0.6, 1e-14);
  // P⁺ = P − K S Kᵀ per axis.
  EXPECT_NEAR(post->P(0, 0), 2.0 / 3.0, 1e-14);
  EXPECT_NEAR(post->P(0, 2), 1.0 / 3.0, 1e-14);
  EXPECT_NEAR(post->P(2, 2), 5.0 / 3.0, 1e-14);
  EXPECT_NEAR(post->P(1, 1), 1.2, 1e-14);
  EXPECT_NEAR(post->P(1, 3), 0.2, 1e-14);
  EXPECT_NEAR(post->P(3, 3), 0.95, 1e-14);
  EXPECT_NEAR(post->P(0, 1), 0.0, 1e-15);
  EXPECT_EQ(post->P, post->P.transpose());
}

TEST(Kalman, UpdateMatchesInformationForm) {
  // Second method: P⁺ = (P⁻¹ + Hᵀ R⁻¹ H)⁻¹, x⁺ = P⁺ (P⁻¹ x + Hᵀ R⁻¹ z), by explicit inverses.
  TargetGaussian prior;
  prior.x << 3.0, -2.0, 1.0, 0.25;
  Mat4 A;
  A << 1.0, 0.2, 0.3, 0.0, 0.1, 1.5, 0.0, 0.4, 0.0, 0.3, 0.8, 0.1, 0.2, 0.0, 0.1, 0.6;
  prior.P = A * A.transpose() + 0.1 * Mat4::Identity();
  Mat2 R;
  R << 0.7, 0.25, 0.25, 1.9;
  const Vec2 z(3.8, -1.1);
  Mat24 H = Mat24::Zero();
  H.leftCols<2>().setIdentity();
  const Mat4 info = prior.P.inverse() + H.transpose() * R.inverse() * H;
  const Mat4 P_expected = info.inverse();
  const Vec4 x_expected =
      P_expected * (prior.P.inverse() * prior.x + H.transpose() * R.inverse() * z);
  const auto post = kalmanUpdate<4, 2>(prior, z, R);
  ASSERT_TRUE(post.has_value());
  EXPECT_LT((post->x - x_expected).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((post->P - P_expected).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(Kalman, TreeUpdateIsTheFusionOfTwoEstimates) {
  // H = I₃: the update is the product of N(x, P) and N(z, R) (x⁺ = P⁺ (P⁻¹x + R⁻¹z)). With
  // diagonal P and R each component is the inverse-variance average.
  TreeGaussian prior;
  prior.x << 4.0, 5.0, 1.2;
  prior.P = Eigen::Vector3d(1.0, 0.5, 0.04).asDiagonal();
  const Eigen::Matrix3d R = Eigen::Vector3d(3.0, 0.5, 0.01).asDiagonal();
  const auto post = kalmanUpdate<3, 3>(prior, Eigen::Vector3d(8.0, 4.0, 1.0), R);
  ASSERT_TRUE(post.has_value());
  EXPECT_NEAR(post->x(0), (4.0 / 1.0 + 8.0 / 3.0) / (1.0 + 1.0 / 3.0), 1e-14);
  EXPECT_NEAR(post->x(1), 4.5, 1e-14);
  EXPECT_NEAR(post->x(2), (1.2 / 0.04 + 1.0 / 0.01) / (1.0 / 0.04 + 1.0 / 0.01), 1e-14);
  EXPECT_NEAR(post->P(0, 0), 0.75, 1e-14);
  EXPECT_NEAR(post->P(1, 1), 0.25, 1e-14);
  EXPECT_NEAR(post->P(2, 2), 0.008, 1e-15);
}

TEST(Kalman, IndefiniteInnovationCovarianceIsRefused) {
  TargetGaussian prior;
  prior.P = Mat4::Identity();
  const auto post = kalmanUpdate<4, 2>(prior, Vec2(1.0, 1.0), Mat2(-5.0 * Mat2::Identity()));
  EXPECT_FALSE(post.has_value());
}

}  // namespace
}  // namespace canopy::agents::tracking
