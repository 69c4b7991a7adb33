#include "agents/fusion/small_cholesky.h"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <limits>

#include "core/random.h"
#include "fusion_test_support.h"

namespace canopy::agents::fusion {
namespace {

template <int N>
void checkAgainstLu(std::uint64_t seed) {
  RandomStream rng(seed, "test.small_cholesky");
  for (int trial = 0; trial < 200; ++trial) {
    const Eigen::Matrix<double, N, N> A = test::randomSpd<N>(rng, 0.05);
    const Eigen::Matrix<double, N, 1> b = test::randomVector<N>(rng, 3.0);
    const SmallCholesky<N> cholesky(A);
    ASSERT_TRUE(cholesky.ok());
    const Eigen::Matrix<double, N, N> inverse = A.inverse();  // LU: a second method
    const double scale = inverse.norm();
    EXPECT_LT((cholesky.inverse() - inverse).norm() / scale, 1e-10);
    EXPECT_EQ(cholesky.inverse(), cholesky.inverse().transpose());
    EXPECT_LT((A * cholesky.solve(b) - b).norm(), 1e-10 * (1.0 + b.norm()));
  }
}

TEST(SmallCholesky, InverseAndSolveMatchLu) {
  checkAgainstLu<2>(1);
  checkAgainstLu<3>(2);
  checkAgainstLu<4>(3);
}

TEST(SmallCholesky, RejectsMatricesThatAreNotPositiveDefinite) {
  EXPECT_FALSE(SmallCholesky<2>(Mat2{{1.0, 2.0}, {2.0, 1.0}}).ok());  // eigenvalues 3, −1
  EXPECT_FALSE(SmallCholesky<4>(Mat4::Zero()).ok());
  Mat4 nan = Mat4::Identity();
  nan(3, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(SmallCholesky<4>(nan).ok());
  EXPECT_TRUE(SmallCholesky<4>(Mat4::Identity()).ok());
}

}  // namespace
}  // namespace canopy::agents::fusion
