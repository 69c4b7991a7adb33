#include "agents/tracking/motion_model.h"

namespace canopy::agents::tracking {

Mat4 ncvTransition(double tau) {
  Mat4 F = Mat4::Identity();
  F(0, 2) = tau;  // px ← px + τ vx
  F(1, 3) = tau;  // py ← py + τ vy
  return F;
}

Mat4 ncvProcessNoise(double tau, double sigma_a) {
  const double q = sigma_a * sigma_a;  // σ_a² (m²/s⁴)
  const double tau2 = tau * tau;
  const double tau3 = tau2 * tau;
  const double tau4 = tau3 * tau;
  Mat4 Q = Mat4::Zero();
  Q(0, 0) = Q(1, 1) = q * tau4 / 4.0;                      // σ_a² τ⁴/4
  Q(0, 2) = Q(2, 0) = Q(1, 3) = Q(3, 1) = q * tau3 / 2.0;  // σ_a² τ³/2
  Q(2, 2) = Q(3, 3) = q * tau2;                            // σ_a² τ²
  return Q;
}

TargetGaussian predictNcv(const TargetGaussian& posterior, double tau, double sigma_a) {
  const Mat4 F = ncvTransition(tau);
  TargetGaussian prior;
  prior.x = F * posterior.x;                                                       // x̄ = F x
  const Mat4 P = F * posterior.P * F.transpose() + ncvProcessNoise(tau, sigma_a);  // F P Fᵀ + Q
  prior.P = 0.5 * (P + P.transpose());
  return prior;
}

}  // namespace canopy::agents::tracking
