// The JPDAF step seen through the Tracker: association probabilities and PDA mixtures against
// formulas written out independently of the implementation.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "agents/tracking/tracker.h"
#include "test_support.h"

namespace canopy::agents::tracking {
namespace {

using test::discFootprint;
using test::gaussianDensity;
using test::targetObservation;

const TargetTrack* find(const Tracker& tracker, TrackKey key) {
  for (const TargetTrack& track : tracker.targets()) {
    if (track.key == key) return &track;
  }
  return nullptr;
}

// The NCV prediction of P₀ = I over τ, per axis, by hand: [[1 + τ² + σ²τ⁴/4, τ + σ²τ³/2],
// [·, 1 + σ²τ²]].
struct AxisPrior {
  double pp, pv, vv;
};
AxisPrior predictedIdentity(double tau, double sigma_a) {
  const double q = sigma_a * sigma_a;
  return {1.0 + tau * tau + q * std::pow(tau, 4) / 4.0, tau + q * std::pow(tau, 3) / 2.0,
          1.0 + q * tau * tau};
}

TEST(Jpdaf, SharedMeasurementSplitsProbability) {
  // Two tracks at (∓1, 0) share one measurement. Events: both missed, z → track 1, z → track 2,
  // with parametric JPDA weights (1 − P_D P_G)², P_D N₁/λ (1 − P_D P_G), P_D N₂/λ (1 − P_D P_G):
  //   β₁ = P_D N₁ / (λ (1 − P_D P_G) + P_D (N₁ + N₂)).
  TrackingConfig config;
  config.survival_probability = 1.0;  // ψ = 1: JIPDA's weights are JPDA's (existence.h)
  const double tau = 0.2, r = 0.5;
  Tracker tracker(0, config);
  tracker.preseed(0, 1, Vec4(-1.0, 0.0, 0.0, 0.0));
  tracker.preseed(1, 1, Vec4(1.0, 0.0, 0.0, 0.0));
  tracker.predict(tau);
  sensing::Scan scan;
  const Vec2 z(0.3, 0.2);
  scan.observations.push_back(targetObservation(z, r * Mat2::Identity()));
  tracker.update(scan, discFootprint(Vec2::Zero(), 50.0), OcclusionMap());

  const AxisPrior a = predictedIdentity(tau, config.sigma_a);
  const Mat2 S = (a.pp + r) * Mat2::Identity();
  const Vec2 nu1 = z - Vec2(-1.0, 0.0), nu2 = z - Vec2(1.0, 0.0);
  const double N1 = gaussianDensity(nu1, S), N2 = gaussianDensity(nu2, S);
  const double PD = config.p_detect, PG = config.gate_probability, lambda = config.clutter_density;
  const double denominator = lambda * (1.0 - PD * PG) + PD * (N1 + N2);
  const double beta1 = PD * N1 / denominator, beta2 = PD * N2 / denominator;

  // Each posterior mean is x̄ + β K ν with K = (P_pp, P_pv) / (P_pp + r) per axis.
  const double k_p = a.pp / (a.pp + r), k_v = a.pv / (a.pp + r);
  const TargetTrack* t1 = find(tracker, {-1, 0});
  const TargetTrack* t2 = find(tracker, {-1, 1});
  ASSERT_TRUE(t1 && t2);
  EXPECT_NEAR(t1->posterior.x(0), -1.0 + beta1 * k_p * nu1.x(), 1e-12);
  EXPECT_NEAR(t1->posterior.x(1), beta1 * k_p * nu1.y(), 1e-12);
  EXPECT_NEAR(t1->posterior.x(2), beta1 * k_v * nu1.x(), 1e-12);
  EXPECT_NEAR(t2->posterior.x(0), 1.0 + beta2 * k_p * nu2.x(), 1e-12);
  EXPECT_NEAR(t2->posterior.x(3), beta2 * k_v * nu2.y(), 1e-12);
  EXPECT_TRUE(t1->detected && t2->detected);
  EXPECT_EQ(tracker.targets().size(), 2u);  // the shared measurement was gated: no birth
}

TEST(Jpdaf, LoneTrackReducesToPdaClosedForm) {
  // Classic PDA (Bar-Shalom, Daum & Huang 2009) with one S for all measurements:
  //   e_j = exp(−d_j²/2), b = λ |2πS|^½ (1 − P_D P_G) / P_D, β_j = e_j / (b + Σe), β₀ = b / (b +
  //   Σe), x = x̄ + K ν̄ with ν̄ = Σ β_j ν_j, P = β₀ P̄ + (1 − β₀) (P̄ − K S Kᵀ) + K (Σ β_j ν_j ν_jᵀ − ν̄
  //   ν̄ᵀ) Kᵀ.
  TrackingConfig config;
  config.survival_probability = 1.0;  // ψ = 1: JIPDA's weights are JPDA's (existence.h)
  config.clutter_density = 0.05;      // large enough that β₀ and the spread term matter
  const double tau = 0.2, r = 0.4;
  Tracker tracker(0, config);
  tracker.preseed(0, 1, Vec4(2.0, 3.0, 0.0, 0.0));
  tracker.predict(tau);
  const Vec2 centre(2.0, 3.0);
  const Vec2 zs[3] = {Vec2(2.5, 3.1), Vec2(1.2, 2.6), Vec2(2.2, 4.4)};
  sensing::Scan scan;
  for (const Vec2& z : zs) scan.observations.push_back(targetObservation(z, r * Mat2::Identity()));
  tracker.update(scan, discFootprint(Vec2::Zero(), 50.0), OcclusionMap());
  ASSERT_EQ(tracker.targets().size(), 1u);  // every measurement gated: no birth
  const TargetTrack& track = tracker.targets().front();

  const AxisPrior a = predictedIdentity(tau, config.sigma_a);
  Mat4 P_bar = Mat4::Zero();
  for (int axis = 0; axis < 2; ++axis) {
    P_bar(axis, axis) = a.pp;
    P_bar(axis, axis + 2) = P_bar(axis + 2, axis) = a.pv;
    P_bar(axis + 2, axis + 2) = a.vv;
  }
  const double s = a.pp + r;  // S = s I₂
  Mat42 K = Mat42::Zero();
  K(0, 0) = K(1, 1) = a.pp / s;
  K(2, 0) = K(3, 1) = a.pv / s;
  const double PD = config.p_detect, PG = config.gate_probability;
  const double b = config.clutter_density * 2.0 * std::numbers::pi * s * (1.0 - PD * PG) / PD;
  double e[3], sum_e = 0.0;
  for (int j = 0; j < 3; ++j) sum_e += e[j] = std::exp(-0.5 * (zs[j] - centre).squaredNorm() / s);
  const double beta0 = b / (b + sum_e);
  Vec2 nu_bar = Vec2::Zero();
  Mat2 spread = Mat2::Zero();
  for (int j = 0; j < 3; ++j) {
    const double beta = e[j] / (b + sum_e);
    const Vec2 nu = zs[j] - centre;
    nu_bar += beta * nu;
    spread += beta * nu * nu.transpose();
  }
  spread -= nu_bar * nu_bar.transpose();
  const Vec4 x = Vec4(2.0, 3.0, 0.0, 0.0) + K * nu_bar;
  const Mat4 P_c = P_bar - K * (s * Mat2::Identity()) * K.transpose();
  const Mat4 P = beta0 * P_bar + (1.0 - beta0) * P_c + K * spread * K.transpose();
  EXPECT_GT(beta0, 0.01);
  EXPECT_LT((track.posterior.x - x).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((track.posterior.P - P).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(Jpdaf, LabelsNeverMix) {
  TrackingConfig config;
  config.survival_probability = 1.0;  // ψ = 1: JIPDA's weights are JPDA's (existence.h)
  Tracker tracker(0, config);
  tracker.preseed(0, 1, Vec4(0.0, 0.0, 0.0, 0.0));
  tracker.predict(0.2);
  sensing::Scan scan;
  scan.observations.push_back(targetObservation(Vec2(0.1, 0.0), Mat2::Identity(), 2));
  tracker.update(scan, discFootprint(Vec2::Zero(), 50.0), OcclusionMap());
  ASSERT_EQ(tracker.targets().size(), 2u);
  const TargetTrack* seeded = find(tracker, {-1, 0});
  ASSERT_TRUE(seeded);
  EXPECT_FALSE(seeded->detected);
  EXPECT_EQ(seeded->posterior.x, seeded->prior.x);  // the miss hypothesis is the prediction
  const TargetTrack* born = find(tracker, {0, 0});
  ASSERT_TRUE(born);
  EXPECT_EQ(born->label, 2);
  EXPECT_EQ(born->status, TrackStatus::tentative);
}

}  // namespace
}  // namespace canopy::agents::tracking
