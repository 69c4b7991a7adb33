// Track management: birth, confirmation, deletion, pre-seeding, occlusion survival, trees, and
// bad input on the per-step path.
#include "agents/tracking/tracker.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/random.h"
#include "sensing/noise.h"
#include "test_support.h"

namespace canopy::agents::tracking {
namespace {

using test::addUnknown;
using test::discFootprint;
using test::unknownTrack;
using test::targetObservation;
using test::treeObservation;

constexpr double kDt = 0.2;  // s

// The M-of-N rule with deletion by covariance and misses: the tracker before existences.
TrackingConfig mOfN() {
  TrackingConfig config;
  config.confirmation = TrackConfirmation::m_of_n;
  return config;
}

const sensing::Footprint kWide = discFootprint(Vec2::Zero(), 100.0);

void step(Tracker& tracker, const sensing::Scan& scan, const sensing::Footprint& footprint = kWide,
          const OcclusionMap& map = OcclusionMap()) {
  tracker.predict(kDt);
  tracker.update(scan, footprint, map);
  tracker.deleteStale();
}

sensing::Scan scanWith(const Vec2& z, const Mat2& R = 0.3 * Mat2::Identity()) {
  sensing::Scan scan;
  scan.observations.push_back(targetObservation(z, R));
  return scan;
}

TEST(Tracker, PreseededTracksAreConfirmedWithTheirKeys) {
  TrackingConfig config;
  config.preseed_variance = Vec4(2.0, 3.0, 0.5, 0.25);
  Tracker tracker(4, config);
  tracker.preseed(0, 1, Vec4(1.0, 2.0, 0.0, 0.0));
  tracker.preseed(3, 1, Vec4(10.0, 2.0, 0.0, 0.0));
  ASSERT_EQ(tracker.targets().size(), 2u);
  const TargetTrack& t = tracker.targets()[1];
  EXPECT_EQ(t.key, (TrackKey{-1, 3}));
  EXPECT_EQ(t.status, TrackStatus::confirmed);
  EXPECT_EQ(t.posterior.P, Mat4(config.preseed_variance.asDiagonal()));
  // A measurement of target 3 updates its track; nothing is born.
  step(tracker, scanWith(Vec2(10.2, 2.1)));
  EXPECT_EQ(tracker.diagnostics().births, 0);
  EXPECT_TRUE(tracker.targets()[1].detected);
  EXPECT_FALSE(tracker.targets()[0].detected);
}

TEST(Tracker, ClutterBirthIsDroppedWhenNotConfirmed) {
  Tracker tracker(2, mOfN());
  step(tracker, scanWith(Vec2(5.0, 5.0)));
  ASSERT_EQ(tracker.targets().size(), 1u);
  EXPECT_EQ(tracker.targets()[0].key, (TrackKey{2, 0}));
  EXPECT_EQ(tracker.targets()[0].status, TrackStatus::tentative);
  EXPECT_EQ(tracker.diagnostics().births, 1);
  step(tracker, sensing::Scan{});  // scan 2: one hit so far, one chance left
  EXPECT_EQ(tracker.targets().size(), 1u);
  step(tracker, sensing::Scan{});  // scan 3: 1 of 3, cannot reach 2 of 3
  EXPECT_TRUE(tracker.targets().empty());
  EXPECT_EQ(tracker.diagnostics().deletions, 1);
}

TEST(Tracker, TwoHitsOutOfThreeConfirm) {
  Tracker tracker(0, mOfN());
  step(tracker, scanWith(Vec2(5.0, 5.0)));
  step(tracker, sensing::Scan{});
  step(tracker, scanWith(Vec2(5.1, 4.9)));
  ASSERT_EQ(tracker.targets().size(), 1u);
  EXPECT_EQ(tracker.targets()[0].status, TrackStatus::confirmed);
  EXPECT_EQ(tracker.targets()[0].key, (TrackKey{0, 0}));
  EXPECT_EQ(tracker.targets()[0].hits, 2);
  EXPECT_EQ(tracker.targets()[0].scans, 3);

  Tracker quick(0, mOfN());  // hits in scans 1 and 2 confirm at scan 2
  step(quick, scanWith(Vec2(5.0, 5.0)));
  step(quick, scanWith(Vec2(5.0, 5.1)));
  EXPECT_EQ(quick.targets()[0].status, TrackStatus::confirmed);
}

TEST(Tracker, OnlyMeasurementsOutsideTheBirthGateStartTracks) {
  // A track at the origin with P₀ = I predicts S = (1 + τ² + σ_a²τ⁴/4 + r) I₂. A measurement at
  // Mahalanobis d² = 10 is outside the association gate (7.82) but inside the birth gate
  // (−2 ln 10⁻⁴ = 18.42): it neither updates the track nor starts one. At d² = 25 it starts one.
  const double r = 0.5;
  const double s = 1.0 + kDt * kDt + std::pow(kDt, 4) / 4.0 + r;
  for (const double d2 : {10.0, 25.0}) {
    Tracker tracker(0, TrackingConfig{});
    tracker.preseed(0, 1, Vec4::Zero());
    step(tracker, scanWith(Vec2(std::sqrt(d2 * s), 0.0), r * Mat2::Identity()));
    EXPECT_FALSE(tracker.targets()[0].detected);
    EXPECT_EQ(tracker.targets().size(), d2 < 18.42 ? 1u : 2u) << d2;
  }
}

TEST(Tracker, HitNeedsTheMeasurementMoreLikelyThanNot) {
  // A tentative track 3 m from a confirmed one gates the confirmed one's next measurements but
  // takes only a small share of them (β ≈ 0.1): they are not hits, and it is dropped at scan 3.
  TrackingConfig config = mOfN();
  config.preseed_variance = Vec4(0.1, 0.1, 0.01, 0.01);
  Tracker tracker(0, config);
  tracker.preseed(0, 1, Vec4::Zero());
  const Mat2 R = 0.3 * Mat2::Identity();
  sensing::Scan first;
  first.observations.push_back(targetObservation(Vec2(0.0, 0.0), R));
  first.observations.push_back(targetObservation(Vec2(3.0, 0.0), R));  // d² ≈ 22: a birth
  step(tracker, first);
  ASSERT_EQ(tracker.targets().size(), 2u);
  step(tracker, scanWith(Vec2(1.0, 0.0), R));
  ASSERT_EQ(tracker.targets().size(), 2u);
  const TargetTrack& tentative = tracker.targets()[1];
  EXPECT_TRUE(tentative.detected);  // gated ...
  EXPECT_EQ(tentative.hits, 1);     // ... but not a hit
  EXPECT_EQ(tentative.status, TrackStatus::tentative);
  step(tracker, scanWith(Vec2(1.0, 0.0), R));
  ASSERT_EQ(tracker.targets().size(), 1u);
  EXPECT_EQ(tracker.targets()[0].key, (TrackKey{-1, 0}));
}

TEST(Tracker, DeletesWhenPositionTraceExceedsThreshold) {
  // Coasting from P₀ = I, n steps of τ give per axis (closed form, sum of F^i Q Fⁱᵀ):
  //   P_pp(n) = 1 + (nτ)² + σ_a² τ⁴ n (4n² − 1) / 12, and tr(P_pos) = 2 P_pp.
  TrackingConfig config = mOfN();
  Tracker tracker(0, config);
  addUnknown(tracker, {unknownTrack(0, Vec4::Zero(), Mat4::Identity())});  // known: never deleted
  auto trace = [&](int n) {
    return 2.0 *
           (1.0 + std::pow(n * kDt, 2) +
            config.sigma_a * config.sigma_a * std::pow(kDt, 4) * n * (4.0 * n * n - 1.0) / 12.0);
  };
  int n_delete = 1;
  while (trace(n_delete) <= config.delete_trace) ++n_delete;
  for (int n = 1; n < n_delete; ++n) step(tracker, sensing::Scan{});
  ASSERT_EQ(tracker.targets().size(), 1u);
  const Mat4& P = tracker.targets()[0].posterior.P;
  EXPECT_NEAR(P(0, 0) + P(1, 1), trace(n_delete - 1), 1e-9);
  step(tracker, sensing::Scan{});
  EXPECT_TRUE(tracker.targets().empty());
  EXPECT_EQ(tracker.diagnostics().deletions, 1);
}

TEST(Tracker, ExpectedMissRuleDeletesOnlyVisibleTracks) {
  TrackingConfig config = mOfN();
  config.delete_misses = 3;
  Tracker tracker(0, config);
  const Mat4 P0 = Mat4::Identity();  // people the scenario does not name (known: never deleted)
  addUnknown(tracker, {unknownTrack(0, Vec4(5.0, 5.0, 0.0, 0.0), P0),     // in the open
                       unknownTrack(1, Vec4(80.0, 0.0, 0.0, 0.0), P0),    // outside the footprint
                       unknownTrack(2, Vec4(-5.0, -5.0, 0.0, 0.0), P0)});  // under a known crown
  const sensing::Footprint footprint = discFootprint(Vec2::Zero(), 20.0);
  const OcclusionMap map({world::TreeDef::disc(Vec2(-5.0, -5.0), 3.0)});
  step(tracker, sensing::Scan{}, footprint, map);
  step(tracker, sensing::Scan{}, footprint, map);
  ASSERT_EQ(tracker.targets().size(), 3u);
  EXPECT_EQ(tracker.targets()[0].expected_misses, 2);
  step(tracker, sensing::Scan{}, footprint, map);
  ASSERT_EQ(tracker.targets().size(), 2u);
  EXPECT_EQ(tracker.targets()[0].key, (TrackKey{0, 1}));
  EXPECT_EQ(tracker.targets()[1].key, (TrackKey{0, 2}));
  EXPECT_EQ(tracker.targets()[0].expected_misses, 0);
  EXPECT_EQ(tracker.targets()[1].expected_misses, 0);
}

TEST(Tracker, SurvivesOcclusionAndReassociates) {
  // A target walks at (1, 0.5) m/s under a static UAV; it is detected for 10 s, hidden for 3 s
  // (15 steps at 0.2 s), then seen again. Its track must keep its key and no track be reborn.
  TrackingConfig config = mOfN();
  Tracker tracker(1, config);
  RandomStream rng(11, "tracker_test_occlusion");
  const sensing::SensorQuality quality;
  const Vec2 uav(0.0, 0.0);
  Vec2 truth(-10.0, -5.0);
  const Vec2 velocity(1.0, 0.5);
  TrackKey key;
  for (int k = 0; k < 90; ++k) {
    truth += kDt * velocity;
    sensing::Scan scan;
    const bool hidden = k >= 50 && k < 65;
    if (!hidden) {
      const Vec2 z = truth + rng.gaussian(sensing::rangeBearingCovariance(truth, uav, quality));
      scan.observations.push_back(
          targetObservation(z, sensing::rangeBearingCovariance(z, uav, quality)));
    }
    step(tracker, scan);
    ASSERT_EQ(tracker.targets().size(), 1u) << "step " << k;
    if (k == 49) {
      key = tracker.targets()[0].key;
      EXPECT_EQ(tracker.targets()[0].status, TrackStatus::confirmed);
    }
    if (k == 64) {
      EXPECT_FALSE(tracker.targets()[0].detected);
    }
  }
  const TargetTrack& track = tracker.targets()[0];
  EXPECT_EQ(track.key, key);
  EXPECT_TRUE(track.detected);
  EXPECT_EQ(tracker.diagnostics().births, 1);
  EXPECT_LT((track.posterior.x.head<2>() - truth).norm(), 1.0);
}

TEST(Tracker, StaticTreeConverges) {
  TrackingConfig config;
  Tracker tracker(0, config);
  RandomStream rng(5, "tracker_test_tree");
  const sensing::SensorQuality quality;
  const Vec2 uav(0.0, 0.0), centre(6.0, 4.0);
  const double radius = 1.5, sigma_r = 0.1;
  for (int k = 0; k < 60; ++k) {
    const Vec2 z = centre + rng.gaussian(sensing::rangeBearingCovariance(centre, uav, quality));
    sensing::Scan scan;
    scan.observations.push_back(treeObservation(z, sensing::rangeBearingCovariance(z, uav, quality),
                                                radius + sigma_r * rng.normal(),
                                                sigma_r * sigma_r));
    step(tracker, scan);
  }
  ASSERT_EQ(tracker.trees().size(), 1u);
  EXPECT_TRUE(tracker.targets().empty());  // tree observations never start target tracks
  const TreeTrack& tree = tracker.trees()[0];
  EXPECT_EQ(tree.status, TrackStatus::confirmed);
  EXPECT_EQ(tree.label, sensing::kTreeLabel);
  EXPECT_LT((tree.posterior.x.head<2>() - centre).norm(), 0.5);
  EXPECT_NEAR(tree.posterior.x(2), radius, 0.2);
}

TEST(Tracker, TreeRadiusNeverBelowMinimum) {
  TrackingConfig config;
  config.tree_min_radius = 0.4;
  Tracker tracker(0, config);
  for (int k = 0; k < 5; ++k) {
    sensing::Scan scan;  // a zero-variance radius of 0 (σ_r = 0 and a clamped draw)
    scan.observations.push_back(treeObservation(Vec2(3.0, 3.0), Mat2::Identity(), 0.0, 0.0));
    step(tracker, scan);
    ASSERT_EQ(tracker.trees().size(), 1u);
    EXPECT_GE(tracker.trees()[0].posterior.x(2), 0.4);
  }
}

TEST(Tracker, BadInputDoesNotBreakTheStep) {
  TrackingConfig config;
  Tracker tracker(0, config);
  step(tracker, sensing::Scan{});  // empty scan, no tracks
  tracker.preseed(0, 1, Vec4::Zero());
  step(tracker, sensing::Scan{});  // empty scan with a track: a miss
  sensing::Scan scan;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  scan.observations.push_back(targetObservation(Vec2(nan, 0.0), Mat2::Identity()));
  scan.observations.push_back(targetObservation(Vec2(0.1, 0.0), Mat2::Zero()));
  scan.observations.push_back(targetObservation(Vec2(0.1, 0.0), Mat2(-Mat2::Identity())));
  scan.observations.push_back(treeObservation(Vec2(1.0, 1.0), Mat2::Identity(), nan, 0.01));
  step(tracker, scan);  // every observation is unusable: ignored
  ASSERT_EQ(tracker.targets().size(), 1u);
  EXPECT_TRUE(tracker.trees().empty());
  EXPECT_EQ(tracker.diagnostics().births, 0);
  EXPECT_TRUE(tracker.targets()[0].posterior.x.allFinite());
}

TEST(Tracker, CrowdedClusterBeyondCapIsApproximated) {
  // Ten targets 0.3 m apart and ten measurements among them: one cluster with far more than
  // 10 000 feasible joint events.
  TrackingConfig config;
  Tracker tracker(0, config);
  for (int t = 0; t < 10; ++t) tracker.preseed(t, 1, Vec4(0.3 * t, 0.0, 0.0, 0.0));
  sensing::Scan scan;
  for (int j = 0; j < 10; ++j) {
    scan.observations.push_back(
        targetObservation(Vec2(0.3 * j + 0.05, 0.1), 0.5 * Mat2::Identity()));
  }
  step(tracker, scan);
  EXPECT_EQ(tracker.diagnostics().approximated_clusters, 1);
  ASSERT_EQ(tracker.targets().size(), 10u);
  for (const TargetTrack& track : tracker.targets()) {
    EXPECT_TRUE(track.detected);
    EXPECT_TRUE(track.posterior.x.allFinite());
    EXPECT_TRUE(track.posterior.P.allFinite());
    EXPECT_LT(track.posterior.P.trace(), track.prior.P.trace());
  }
  EXPECT_EQ(tracker.diagnostics().non_positive_covariances, 0);
}

TEST(Tracker, ManyMeasurementsInOneGateBeyondCap) {
  // One track, 400 measurements in its gate, a cap of 50: the cluster is approximated by belief
  // propagation, which is exact on this tree-shaped cluster, so the result is still the PDA one
  // computed by exact enumeration under a large cap.
  auto run = [](int cap) {
    TrackingConfig config;
    config.max_hypotheses = cap;
    Tracker tracker(0, config);
    tracker.preseed(0, 1, Vec4::Zero());
    sensing::Scan scan;
    for (int j = 0; j < 400; ++j) {
      const double angle = 0.1 * j, radius = 0.005 * j;
      scan.observations.push_back(targetObservation(
          Vec2(radius * std::cos(angle), radius * std::sin(angle)), 0.5 * Mat2::Identity()));
    }
    step(tracker, scan);
    return tracker;
  };
  const Tracker approximated = run(50);
  const Tracker exact = run(10000);
  EXPECT_EQ(approximated.diagnostics().approximated_clusters, 1);
  EXPECT_EQ(exact.diagnostics().approximated_clusters, 0);
  ASSERT_EQ(approximated.targets().size(), 1u);
  ASSERT_EQ(exact.targets().size(), 1u);
  const TargetGaussian& a = approximated.targets()[0].posterior;
  const TargetGaussian& e = exact.targets()[0].posterior;
  EXPECT_LT((a.x - e.x).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LT((a.P - e.P).cwiseAbs().maxCoeff(), 1e-9);
}

}  // namespace
}  // namespace canopy::agents::tracking

namespace canopy::agents::tracking {
namespace {

// tracking.negative_information: a known person whose scan saw nothing, with the camera on one
// side of where it could be, is moved away from what the camera saw (symmetric about the x axis:
// y stays); off, it keeps its prediction exactly.
TEST(Tracker, NegativeInformationMovesAMissedTrackAwayFromTheView) {
  const sensing::Footprint right = discFootprint(Vec2(3.0, 0.0), 3.0);  // sees x ∈ [0, 6]
  for (const bool negative : {false, true}) {
    TrackingConfig config;
    config.negative_information = negative;
    config.preseed_variance = Vec4(4.0, 4.0, 0.25, 0.25);
    Tracker tracker(0, config);
    tracker.preseed(0, 1, Vec4(0.0, 0.0, 0.0, 0.0));
    step(tracker, sensing::Scan{}, right);
    const TargetTrack& t = tracker.targets()[0];
    if (!negative) {
      EXPECT_EQ(t.posterior.x, t.prior.x);
      EXPECT_EQ(t.posterior.P, t.prior.P);
      continue;
    }
    EXPECT_LT(t.posterior.x(0), t.prior.x(0) - 0.5);        // pushed to the unseen side
    EXPECT_NEAR(t.posterior.x(1), t.prior.x(1), 1e-9);      // the view is symmetric in y
    EXPECT_LT(t.posterior.P(0, 0), t.prior.P(0, 0));        // half the spread is ruled out
  }
}

}  // namespace
}  // namespace canopy::agents::tracking
