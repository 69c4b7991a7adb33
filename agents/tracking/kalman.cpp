#include "agents/tracking/kalman.h"

#include <Eigen/Cholesky>

namespace canopy::agents::tracking {

template <int N, int M>
std::optional<Gaussian<N>> kalmanUpdate(const Gaussian<N>& prior,
                                        const Eigen::Matrix<double, M, 1>& z,
                                        const Eigen::Matrix<double, M, M>& R) {
  using MatM = Eigen::Matrix<double, M, M>;
  using MatN = Eigen::Matrix<double, N, N>;
  using MatNM = Eigen::Matrix<double, N, M>;
  // With H = [I_M 0], H P Hᵀ is P's top-left M×M block and P Hᵀ its first M columns.
  const MatM S = prior.P.template topLeftCorner<M, M>() + R;  // S = H P Hᵀ + R
  const Eigen::LLT<MatM> llt(S);
  if (llt.info() != Eigen::Success) return std::nullopt;
  const MatNM PHt = prior.P.template leftCols<M>();        // P Hᵀ
  const MatNM K = llt.solve(PHt.transpose()).transpose();  // K = P Hᵀ S⁻¹ (S symmetric)
  MatN I_KH = MatN::Identity();
  I_KH.template leftCols<M>() -= K;                                          // I − K H
  const MatN P = I_KH * prior.P * I_KH.transpose() + K * R * K.transpose();  // Joseph form
  Gaussian<N> posterior;
  posterior.x = prior.x + K * (z - prior.x.template head<M>());  // x + K (z − H x)
  posterior.P = 0.5 * (P + P.transpose());
  return posterior;
}

template std::optional<Gaussian<4>> kalmanUpdate<4, 2>(const Gaussian<4>&, const Vec2&,
                                                       const Mat2&);
template std::optional<Gaussian<3>> kalmanUpdate<3, 3>(const Gaussian<3>&, const Eigen::Vector3d&,
                                                       const Eigen::Matrix3d&);

}  // namespace canopy::agents::tracking
