#include "agents/tracking/motion_model.h"

#include <gtest/gtest.h>

namespace canopy::agents::tracking {
namespace {

TEST(MotionModel, ProcessNoiseMatchesClosedForm) {
  // τ = 0.5 s, σ_a = 2 m/s²: σ_a² τ⁴/4 = 4 · 0.0625/4, σ_a² τ³/2 = 4 · 0.125/2, σ_a² τ² = 4 · 0.25.
  const Mat4 Q = ncvProcessNoise(0.5, 2.0);
  Mat4 expected = Mat4::Zero();
  expected(0, 0) = expected(1, 1) = 0.0625;
  expected(0, 2) = expected(2, 0) = expected(1, 3) = expected(3, 1) = 0.25;
  expected(2, 2) = expected(3, 3) = 1.0;
  EXPECT_LT((Q - expected).cwiseAbs().maxCoeff(), 1e-15);
}

TEST(MotionModel, ProcessNoiseIsAccelerationHeldOverTheStep) {
  // Second method: a constant acceleration a ~ N(0, σ_a²) over τ moves the state by
  // g a with g = (τ²/2, τ) per axis, so Q = σ_a² g gᵀ.
  const double tau = 0.2, sigma_a = 1.3;
  const Eigen::Vector2d g(tau * tau / 2.0, tau);
  const Eigen::Matrix2d per_axis = sigma_a * sigma_a * g * g.transpose();
  const Mat4 Q = ncvProcessNoise(tau, sigma_a);
  for (int axis = 0; axis < 2; ++axis) {
    EXPECT_NEAR(Q(axis, axis), per_axis(0, 0), 1e-15);
    EXPECT_NEAR(Q(axis, axis + 2), per_axis(0, 1), 1e-15);
    EXPECT_NEAR(Q(axis + 2, axis + 2), per_axis(1, 1), 1e-15);
  }
  EXPECT_EQ(Q(0, 1), 0.0);  // the axes are independent
  EXPECT_EQ(Q(0, 3), 0.0);
}

TEST(MotionModel, PredictMatchesHandComputation) {
  TargetGaussian g;
  g.x << 1.0, 2.0, 3.0, 4.0;
  g.P = Vec4(1.0, 2.0, 3.0, 4.0).asDiagonal();
  const TargetGaussian p = predictNcv(g, 0.5, 2.0);
  // x axis: F [[1, 0], [0, 3]] Fᵀ = [[1.75, 1.5], [1.5, 3]], plus Q = [[0.0625, 0.25], [0.25, 1]].
  // y axis: F [[2, 0], [0, 4]] Fᵀ = [[3, 2], [2, 4]], plus the same Q.
  EXPECT_NEAR(p.x(0), 2.5, 1e-15);
  EXPECT_NEAR(p.x(1), 4.0, 1e-15);
  EXPECT_NEAR(p.x(2), 3.0, 1e-15);
  EXPECT_NEAR(p.x(3), 4.0, 1e-15);
  Mat4 expected = Mat4::Zero();
  expected(0, 0) = 1.8125;
  expected(0, 2) = expected(2, 0) = 1.75;
  expected(2, 2) = 4.0;
  expected(1, 1) = 3.0625;
  expected(1, 3) = expected(3, 1) = 2.25;
  expected(3, 3) = 5.0;
  EXPECT_LT((p.P - expected).cwiseAbs().maxCoeff(), 1e-14);
}

TEST(MotionModel, StaticTreeDoesNotMove) {
  TreeGaussian g;
  g.x << 3.0, -1.0, 2.0;
  g.P = Eigen::Vector3d(0.5, 0.6, 0.01).asDiagonal();
  const TreeGaussian p = predictStatic(g);
  EXPECT_EQ(p.x, g.x);
  EXPECT_EQ(p.P, g.P);
}

}  // namespace
}  // namespace canopy::agents::tracking
