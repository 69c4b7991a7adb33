#pragma once
// Cholesky factorisation A = L Lᵀ of a small symmetric positive definite matrix (N ≤ 4), and the
// solves the information form needs. Written out because Eigen's LLT sends a matrix right-hand
// side (the solve against I that gives A⁻¹) through its blocked kernels, about 3× slower at
// this size; the fusion step does two of these per track and agent.
#include <Eigen/Core>
#include <cmath>

namespace canopy::agents::fusion {

template <int N>
class SmallCholesky {
 public:
  using Mat = Eigen::Matrix<double, N, N>;
  using Vec = Eigen::Matrix<double, N, 1>;

  /// Factorises A (only its lower triangle is read). ok() is false unless A is positive definite
  /// with finite entries.
  explicit SmallCholesky(const Mat& A) {
    L_.setZero();
    for (int j = 0; j < N; ++j) {
      double d = A(j, j);
      for (int k = 0; k < j; ++k) d -= L_(j, k) * L_(j, k);
      if (!(d > 0.0) || !std::isfinite(d)) return;  // not positive definite (or NaN)
      L_(j, j) = std::sqrt(d);                      // L_jj = √(A_jj − Σ_k L_jk²)
      for (int i = j + 1; i < N; ++i) {
        double v = A(i, j);
        for (int k = 0; k < j; ++k) v -= L_(i, k) * L_(j, k);
        L_(i, j) = v / L_(j, j);  // L_ij = (A_ij − Σ_k L_ik L_jk) / L_jj
      }
    }
    ok_ = true;
  }

  bool ok() const { return ok_; }

  /// A⁻¹ b: L y = b forward, then Lᵀ x = y backward.
  Vec solve(const Vec& b) const {
    Vec y;
    for (int i = 0; i < N; ++i) {
      double v = b(i);
      for (int k = 0; k < i; ++k) v -= L_(i, k) * y(k);
      y(i) = v / L_(i, i);
    }
    Vec x;
    for (int i = N - 1; i >= 0; --i) {
      double v = y(i);
      for (int k = i + 1; k < N; ++k) v -= L_(k, i) * x(k);
      x(i) = v / L_(i, i);
    }
    return x;
  }

  /// A⁻¹ = L⁻ᵀ L⁻¹, with M = L⁻¹ from L M = I by forward substitution; symmetrised.
  Mat inverse() const {
    Mat M = Mat::Zero();  // lower triangular
    for (int j = 0; j < N; ++j) {
      M(j, j) = 1.0 / L_(j, j);
      for (int i = j + 1; i < N; ++i) {
        double v = 0.0;
        for (int k = j; k < i; ++k) v -= L_(i, k) * M(k, j);
        M(i, j) = v / L_(i, i);
      }
    }
    const Mat inverse = M.transpose() * M;
    return 0.5 * (inverse + inverse.transpose());
  }

 private:
  Mat L_;  // lower triangular factor
  bool ok_ = false;
};

}  // namespace canopy::agents::fusion
