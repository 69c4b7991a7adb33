// Filter consistency (Bar-Shalom, Li & Kirubarajan 2001, §5.4): over independent runs of a single
// target whose truth follows the NCV model's own process noise, seen by one UAV with the
// range-bearing noise of sensing/noise.h, the ensemble-average NEES and NIS lie inside their
// two-sided 95 % chi-square bounds.
#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <cmath>
#include <vector>

#include "agents/tracking/tracker.h"
#include "core/random.h"
#include "sensing/noise.h"
#include "test_support.h"

namespace canopy::agents::tracking {
namespace {

// χ²_k quantile by the Wilson–Hilferty cube-root approximation (accurate to < 0.1 % for
// k ≥ 100): χ² ≈ k (1 − 2/(9k) + z_p √(2/(9k)))³.
double chiSquareQuantile(int k, double z_p) {
  const double c = 2.0 / (9.0 * k);
  return k * std::pow(1.0 - c + z_p * std::sqrt(c), 3);
}
constexpr double kZ975 = 1.959963984540054;  // standard normal 97.5 % quantile

TEST(Consistency, NeesAndNisWithinChiSquareBounds) {
  constexpr int kRuns = 50, kSteps = 100;
  constexpr double kDt = 0.2;
  // The filter's consistency, not track management: with existence deletion a track whose target
  // left its gate for four scans in a row (one run of 50 here) is deleted and replaced.
  TrackingConfig config;
  config.confirmation = TrackConfirmation::m_of_n;
  const sensing::SensorQuality quality;
  const Vec2 uav(0.0, 0.0);
  const sensing::Footprint footprint = test::discFootprint(uav, 1000.0);
  std::vector<double> nees(kSteps, 0.0), nis(kSteps, 0.0);

  for (int run = 0; run < kRuns; ++run) {
    RandomStream rng(2024, "tracking_consistency", run);
    Vec4 truth(15.0, 10.0, 1.0, 0.5);
    Vec4 estimate = truth;
    for (int i = 0; i < 4; ++i) estimate(i) += std::sqrt(config.preseed_variance(i)) * rng.normal();
    Tracker tracker(0, config);
    tracker.preseed(0, 1, estimate);
    for (int k = 0; k < kSteps; ++k) {
      for (int axis = 0; axis < 2; ++axis) {  // acceleration held over the step: Q(τ) exactly
        const double a = config.sigma_a * rng.normal();
        truth(axis) += kDt * truth(axis + 2) + 0.5 * kDt * kDt * a;
        truth(axis + 2) += kDt * a;
      }
      const Vec2 position = truth.head<2>();
      const Vec2 z =
          position + rng.gaussian(sensing::rangeBearingCovariance(position, uav, quality));
      sensing::Scan scan;
      scan.observations.push_back(
          test::targetObservation(z, sensing::rangeBearingCovariance(z, uav, quality)));

      tracker.predict(kDt);
      const TargetTrack* track = nullptr;
      for (const TargetTrack& t : tracker.targets()) {
        if (t.key == TrackKey{-1, 0}) track = &t;
      }
      ASSERT_NE(track, nullptr);
      const Vec2 nu = z - track->prior.x.head<2>();
      const Mat2 S = track->prior.P.topLeftCorner<2, 2>() + scan.observations[0].R;
      nis[k] += nu.dot(S.ldlt().solve(nu)) / kRuns;  // νᵀ S⁻¹ ν

      tracker.update(scan, footprint, OcclusionMap());
      for (const TargetTrack& t : tracker.targets()) {
        if (t.key == TrackKey{-1, 0}) track = &t;
      }
      const Vec4 e = truth - track->posterior.x;
      nees[k] += e.dot(track->posterior.P.ldlt().solve(e)) / kRuns;  // eᵀ P⁻¹ e
      tracker.deleteStale();
    }
  }

  // The ensemble average of M independent χ²_n samples is χ²_{Mn} / M.
  const double nees_lo = chiSquareQuantile(4 * kRuns, -kZ975) / kRuns;
  const double nees_hi = chiSquareQuantile(4 * kRuns, kZ975) / kRuns;
  const double nis_lo = chiSquareQuantile(2 * kRuns, -kZ975) / kRuns;
  const double nis_hi = chiSquareQuantile(2 * kRuns, kZ975) / kRuns;
  int nees_inside = 0, nis_inside = 0;
  double nees_mean = 0.0, nis_mean = 0.0;
  for (int k = 0; k < kSteps; ++k) {
    nees_inside += nees[k] >= nees_lo && nees[k] <= nees_hi;
    nis_inside += nis[k] >= nis_lo && nis[k] <= nis_hi;
    nees_mean += nees[k] / kSteps;
    nis_mean += nis[k] / kSteps;
  }
  // 95 % of the steps are expected inside; 85 % is 4.5 binomial standard deviations below.
  EXPECT_GE(nees_inside, 85) << "NEES bounds [" << nees_lo << ", " << nees_hi << "]";
  EXPECT_GE(nis_inside, 85) << "NIS bounds [" << nis_lo << ", " << nis_hi << "]";
  EXPECT_GT(nees_mean, nees_lo);
  EXPECT_LT(nees_mean, nees_hi);
  EXPECT_GT(nis_mean, nis_lo);
  EXPECT_LT(nis_mean, nis_hi);
  RecordProperty("nees_mean", std::to_string(nees_mean));
  RecordProperty("nis_mean", std::to_string(nis_mean));
  std::printf(
      "NEES mean %.3f in [%.3f, %.3f], %d/100 steps inside; NIS mean %.3f in [%.3f, %.3f], "
      "%d/100 inside\n",
      nees_mean, nees_lo, nees_hi, nees_inside, nis_mean, nis_lo, nis_hi, nis_inside);
}

}  // namespace
}  // namespace canopy::agents::tracking
