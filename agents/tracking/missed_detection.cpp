#include "agents/tracking/missed_detection.h"

#include <Eigen/Cholesky>
#include <cmath>

namespace canopy::agents::tracking {

const NormalGrid& normalGrid() {
  static const NormalGrid grid = [] {
    NormalGrid g;
    constexpr double h = 2.0 * NormalGrid::kSpan / NormalGrid::kCells;
    double sum = 0.0;
    for (int i = 0; i < NormalGrid::kCells; ++i) {
      g.nodes[i] = -NormalGrid::kSpan + h * (i + 0.5);
      g.weights[i] = std::exp(-0.5 * g.nodes[i] * g.nodes[i]);  // ∝ φ(u_i)
      sum += g.weights[i];
    }
    for (double& w : g.weights) w /= sum;
    return g;
  }();
  return grid;
}

TargetGaussian afterMissedDetection(const TargetGaussian& prior, double p_detect,
                                    const std::function<bool(const Vec2&)>& visible) {
  const Mat2 P_pp = prior.P.topLeftCorner<2, 2>();
  const Eigen::LLT<Mat2> llt(P_pp);
  if (llt.info() != Eigen::Success || !prior.P.allFinite() || !prior.x.allFinite()) return prior;
  const Mat2 L = llt.matrixL();
  const Vec2 p_hat = prior.x.head<2>();
  const NormalGrid& grid = normalGrid();

  // The visible part's moments in u: m_v, f_v, S_v.
  double m_v = 0.0;
  Vec2 f_v = Vec2::Zero();
  Mat2 S_v = Mat2::Zero();
  for (int a = 0; a < NormalGrid::kCells; ++a) {
    for (int b = 0; b < NormalGrid::kCells; ++b) {
      const Vec2 u(grid.nodes[a], grid.nodes[b]);
      if (!visible(p_hat + L * u)) continue;
      const double w = grid.weights[a] * grid.weights[b];
      m_v += w;
      f_v += w * u;
      S_v += w * u * u.transpose();
    }
  }
  const double Z = 1.0 - p_detect * m_v;  // the miss's probability
  if (m_v == 0.0 || !(Z > 0.0)) return prior;
  const Vec2 mean_u = -p_detect * f_v / Z;                                // E[u]
  const Mat2 cov_u = (Mat2::Identity() - p_detect * S_v) / Z - mean_u * mean_u.transpose();
  const Vec2 shift = L * mean_u;                                          // p̂' − p̂
  Mat2 P_pp_after = L * cov_u * L.transpose();                            // Cov[p]
  P_pp_after = 0.5 * (P_pp_after + P_pp_after.transpose());
  if (Eigen::LLT<Mat2>(P_pp_after).info() != Eigen::Success) return prior;  // grid too coarse

  // The velocity by its regression on the position: K = P_vp P_pp⁻¹.
  const Mat2 P_vp = prior.P.bottomLeftCorner<2, 2>();
  const Mat2 K = llt.solve(P_vp.transpose()).transpose();  // (P_pp⁻¹ P_pv)ᵀ = P_vp P_pp⁻¹
  TargetGaussian after;
  after.x.head<2>() = p_hat + shift;
  after.x.tail<2>() = prior.x.tail<2>() + K * shift;  // v̂ + K (p̂' − p̂)
  after.P.topLeftCorner<2, 2>() = P_pp_after;
  after.P.bottomLeftCorner<2, 2>() = K * P_pp_after;  // P'_vp
  after.P.topRightCorner<2, 2>() = after.P.bottomLeftCorner<2, 2>().transpose();
  const Mat2 P_vv = prior.P.bottomRightCorner<2, 2>() - K * P_vp.transpose() +
                    K * P_pp_after * K.transpose();  // P_vv − K P_pv + K P'_pp Kᵀ
  after.P.bottomRightCorner<2, 2>() = 0.5 * (P_vv + P_vv.transpose());
  return after;
}

}  // namespace canopy::agents::tracking
