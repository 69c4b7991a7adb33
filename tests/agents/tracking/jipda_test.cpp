// JIPDA: the probability of existence against Bayes' rule written out by hand, P(visible) from
// sigma points, existence under a known crown against the open, and duplicate merging.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "agents/tracking/duplicates.h"
#include "agents/tracking/existence.h"
#include "agents/tracking/tracker.h"
#include "core/random.h"
#include "test_support.h"

namespace canopy::agents::tracking {
namespace {

using test::discFootprint;
using test::gaussianDensity;
using test::targetObservation;

constexpr double kDt = 0.2;  // s

using test::addUnknown;
using test::unknownTrack;

const TargetTrack* find(const Tracker& tracker, TrackKey key) {
  for (const TargetTrack& t : tracker.targets()) {
    if (t.key == key) return &t;
  }
  return nullptr;
}

// Bayes over "exists" and "does not", for a scan with no measurement at all: the Poisson
// clutter's probability of no false alarm is common to both and cancels.
//   P(exists, nothing) ∝ ψ (1 − P_D P_G),  P(gone, nothing) ∝ 1 − ψ.
double bayesAfterNothing(double psi, double p_d, double p_g) {
  const double exists = psi * (1.0 - p_d * p_g);
  return exists / (exists + (1.0 - psi));
}

TEST(Jipda, ExistenceAfterMissesMatchesBayes) {
  TrackingConfig config;
  Tracker tracker(0, config);
  addUnknown(tracker, {unknownTrack(0, Vec4::Zero(), Mat4::Identity())});
  const sensing::Footprint footprint = discFootprint(Vec2::Zero(), 100.0);
  const double p_s = std::pow(config.survival_probability, kDt);  // per scan
  double r = 1.0;
  for (int k = 0; k < 3; ++k) {
    tracker.predict(kDt);
    tracker.update(sensing::Scan{}, footprint, OcclusionMap());
    r = bayesAfterNothing(p_s * r, config.p_detect, config.gate_probability);
    ASSERT_EQ(tracker.targets().size(), 1u);
    EXPECT_NEAR(tracker.targets()[0].existence, r, 1e-14) << "scan " << k;
    EXPECT_DOUBLE_EQ(tracker.targets()[0].visibility, 1.0);
  }
  EXPECT_NEAR(existenceAfterMiss(0.5, 0.9, 0.98), 0.5 * 0.118 / (0.5 * 0.118 + 0.5), 1e-15);
}

TEST(Jipda, ExistenceAndStateWithOneMeasurementMatchBayes) {
  // One track (P₀ = I, predicted over τ: S = (P_pp + r) I), one measurement z, clutter density λ.
  // With Poisson clutter of mean Λ over the region, the three ways to see exactly z:
  //   H1 exists, z is its detection, no clutter:   ψ P_D N(ν; 0, S) e^{−Λ}
  //   H2 exists, undetected, z is clutter:         ψ (1 − P_D P_G) λ e^{−Λ}
  //   H3 gone, z is clutter:                        (1 − ψ) λ e^{−Λ}
  // r⁺ = (H1 + H2) / (H1 + H2 + H3); given existence the state is the update with weight
  // H1 / (H1 + H2), else the prediction: x = x̄ + w K ν.
  TrackingConfig config;
  config.survival_probability = 0.5;  // ψ = 0.5^0.2 ≈ 0.87: far from 1, so r⁺ moves visibly
  Tracker tracker(0, config);
  addUnknown(tracker, {unknownTrack(0, Vec4::Zero(), Mat4::Identity())});
  tracker.predict(kDt);
  const double r_noise = 0.5;  // m², R = r I
  const Vec2 z(0.9, -0.4);
  sensing::Scan scan;
  scan.observations.push_back(targetObservation(z, r_noise * Mat2::Identity()));
  tracker.update(scan, discFootprint(Vec2::Zero(), 100.0), OcclusionMap());

  const double q = config.sigma_a * config.sigma_a;
  const double pp = 1.0 + kDt * kDt + q * std::pow(kDt, 4) / 4.0;  // predicted P_pp
  const double pv = kDt + q * std::pow(kDt, 3) / 2.0;              // predicted P_pv
  const double psi = std::pow(config.survival_probability, kDt);
  const double density = gaussianDensity(z, (pp + r_noise) * Mat2::Identity());
  const double pd = config.p_detect, pg = config.gate_probability;
  const double lambda = config.clutter_density;
  const double h1 = psi * pd * density;
  const double h2 = psi * (1.0 - pd * pg) * lambda;
  const double h3 = (1.0 - psi) * lambda;
  const double w = h1 / (h1 + h2);

  ASSERT_EQ(tracker.targets().size(), 1u);  // z was gated: no birth
  const TargetTrack& track = tracker.targets()[0];
  EXPECT_NEAR(track.existence, (h1 + h2) / (h1 + h2 + h3), 1e-12);
  const double k_p = pp / (pp + r_noise), k_v = pv / (pp + r_noise);
  EXPECT_NEAR(track.posterior.x(0), w * k_p * z.x(), 1e-12);
  EXPECT_NEAR(track.posterior.x(1), w * k_p * z.y(), 1e-12);
  EXPECT_NEAR(track.posterior.x(2), w * k_v * z.x(), 1e-12);
  EXPECT_NEAR(track.posterior.x(3), w * k_v * z.y(), 1e-12);
}

TEST(Jipda, VisibilityFromSigmaPoints) {
  // Mean on the edge of a disc footprint of radius 10, P_pos = I: the points are the mean
  // (weight 1/3, inside: the footprint is closed), mean ± √3 eₓ (one inside, one outside, 1/6
  // each) and mean ± √3 e_y (both at distance √103 > 10: outside). P(visible) = 1/3 + 1/6.
  const sensing::Footprint footprint = discFootprint(Vec2::Zero(), 10.0);
  const CameraOcclusion camera;
  EXPECT_NEAR(visibleProbability(Vec2(10.0, 0.0), Mat2::Identity(), footprint, OcclusionMap(),
                                 camera, Vec2::Zero()),
              0.5, 1e-15);
  // Under a crown of radius 3 with every point inside (√3 · 1 < 3): hidden; in the open: seen.
  const OcclusionMap map({world::TreeDef::disc(Vec2(5.0, 5.0), 3.0)});
  EXPECT_EQ(
      visibleProbability(Vec2(5.0, 5.0), Mat2::Identity(), footprint, map, camera, Vec2::Zero()),
      0.0);
  EXPECT_NEAR(
      visibleProbability(Vec2(-5.0, 0.0), Mat2::Identity(), footprint, map, camera, Vec2::Zero()),
      1.0, 1e-15);
  // A crown of radius 3 at (3.5, 0): the mean (0.5, 0) lies on its edge (not strictly inside:
  // seen), mean + √3 eₓ = (2.23, 0) under it, mean − √3 eₓ and mean ± √3 e_y (3.46 from its
  // centre) outside. P(visible) = 1 − 1/6.
  const OcclusionMap edge({world::TreeDef::disc(Vec2(3.5, 0.0), 3.0)});
  EXPECT_NEAR(
      visibleProbability(Vec2(0.5, 0.0), Mat2::Identity(), footprint, edge, camera, Vec2::Zero()),
      5.0 / 6.0, 1e-15);
}

TEST(Jipda, VisibilityByLineOfSightBehindAWall) {
  // A wall from (4, −10) to (6, 10) (2 m thick) between the sensor at the origin and a target at
  // (10, 0): every sigma point (P_pos = I, so within √3 of (10, 0)) is behind it. A target at
  // (−10, 0) has nothing in the way. Under the canopy model the wall hides only what is under it.
  const sensing::Footprint footprint = discFootprint(Vec2::Zero(), 30.0);
  const OcclusionMap wall({world::TreeDef::polygon(
      {Vec2(4.0, -10.0), Vec2(6.0, -10.0), Vec2(6.0, 10.0), Vec2(4.0, 10.0)})});
  CameraOcclusion line_of_sight;
  line_of_sight.targets = sensing::OcclusionModel::line_of_sight;
  EXPECT_EQ(visibleProbability(Vec2(10.0, 0.0), Mat2::Identity(), footprint, wall, line_of_sight,
                               Vec2::Zero()),
            0.0);
  EXPECT_NEAR(visibleProbability(Vec2(-10.0, 0.0), Mat2::Identity(), footprint, wall, line_of_sight,
                                 Vec2::Zero()),
              1.0, 1e-15);
  EXPECT_NEAR(visibleProbability(Vec2(10.0, 0.0), Mat2::Identity(), footprint, wall,
                                 CameraOcclusion{}, Vec2::Zero()),
              1.0, 1e-15);
}

// 20 scans without a measurement of a target standing under a crown of radius 5 m, with an
// uncertainty whose sigma points stay under it (P₀ = diag(0.25, 0.25, 0.01, 0.01): after 20
// predictions P_pp = 0.25 + 0.01 · 4² + σ_a² τ⁴ · 20 (4 · 20² − 1) / 12 = 4.67 m², so √3 σ =
// 3.7 m < 5 m): P(visible) = 0, so only survival acts, r = p_S(1 s)^(20 τ) = 0.95⁴ = 0.8145.
// In the open the same track is deleted at the first scan whose Bayes existence (above) falls
// below delete_existence: the fourth (r = 0.920, 0.545, 0.121, 0.016 with the defaults). Both
// are tracks of people the scenario does not name; a known person's is never deleted (below).
TEST(Jipda, UnseenUnderAKnownCrownKeepsExistenceUnseenInTheOpenIsDeleted) {
  TrackingConfig config;
  const Mat4 P0 = Vec4(0.25, 0.25, 0.01, 0.01).asDiagonal();
  const sensing::Footprint footprint = discFootprint(Vec2::Zero(), 30.0);
  const OcclusionMap crown({world::TreeDef::disc(Vec2(5.0, 5.0), 5.0)});

  Tracker hidden(0, config);
  addUnknown(hidden, {unknownTrack(0, Vec4(5.0, 5.0, 0.0, 0.0), P0)});
  for (int k = 0; k < 20; ++k) {
    hidden.predict(kDt);
    hidden.update(sensing::Scan{}, footprint, crown);
    hidden.mergeDuplicates();
    hidden.deleteStale();
    ASSERT_EQ(hidden.targets().size(), 1u) << "scan " << k;
    EXPECT_EQ(hidden.targets()[0].visibility, 0.0) << "scan " << k;
  }
  EXPECT_NEAR(hidden.targets()[0].existence, std::pow(0.95, 4.0), 1e-12);
  EXPECT_GE(hidden.targets()[0].existence, 0.5);

  const double p_s = std::pow(config.survival_probability, kDt);
  int expected_deletion = 0;  // the scan (1-based) at which Bayes' existence drops below 0.05
  for (double r = 1.0; r >= config.delete_existence; ++expected_deletion) {
    r = bayesAfterNothing(p_s * r, config.p_detect, config.gate_probability);
  }
  EXPECT_EQ(expected_deletion, 4);
  Tracker open(0, config);
  addUnknown(open, {unknownTrack(0, Vec4(5.0, 5.0, 0.0, 0.0), P0)});
  int deleted_at = 0;
  for (int k = 1; k <= 20 && deleted_at == 0; ++k) {
    open.predict(kDt);
    open.update(sensing::Scan{}, footprint, OcclusionMap());
    open.mergeDuplicates();
    open.deleteStale();
    if (open.targets().empty()) deleted_at = k;
  }
  EXPECT_EQ(deleted_at, expected_deletion);
}

// A known (pre-seeded) person unseen in the open for 60 s: never deleted, existence 1, lost once
// tr(P_pos) > delete_trace, and its P within the bounds of known_people.h for a 100 × 60 m area
// and walk_speed 1.5 m/s: σ_x² ≤ 100²/12 = 833.3 m², σ_y² ≤ 60²/12 = 300 m², σ_v² ≤ 2.25 m²/s²,
// its mean inside the area. Then a UAV flies over it: a measurement 30 m from the mean, far out
// of an unknown track's gate, is taken by the lost track (no birth), which is held again (its
// mean within 1 m of the person, tr(P_pos) < 1 m²) within 10 scans.
TEST(Jipda, AKnownPersonUnseenForAMinuteIsLostNotDeletedAndReacquired) {
  TrackingConfig config;
  config.walk_speed = 1.5;
  config.area = Aabb{Vec2(0.0, 0.0), Vec2(100.0, 60.0)};
  Tracker tracker(0, config);
  tracker.preseed(0, 1, Vec4(50.0, 30.0, 1.0, 0.5));
  const sensing::Footprint far_away = discFootprint(Vec2(-500.0, -500.0), 10.0);
  bool lost = false;
  for (int k = 1; k <= 300; ++k) {  // 60 s of scans without the person in view
    tracker.predict(kDt);
    tracker.update(sensing::Scan{}, far_away, OcclusionMap());
    tracker.mergeDuplicates();
    tracker.deleteStale();
    ASSERT_EQ(tracker.targets().size(), 1u) << "scan " << k;
    const TargetTrack& t = tracker.targets()[0];
    EXPECT_EQ(t.existence, 1.0);
    EXPECT_LE(t.posterior.P(0, 0), 100.0 * 100.0 / 12.0 * (1 + 1e-12)) << "scan " << k;
    EXPECT_LE(t.posterior.P(1, 1), 60.0 * 60.0 / 12.0 * (1 + 1e-12)) << "scan " << k;
    EXPECT_LE(t.posterior.P(2, 2), 2.25 * (1 + 1e-12)) << "scan " << k;
    EXPECT_LE(t.posterior.P(3, 3), 2.25 * (1 + 1e-12)) << "scan " << k;
    EXPECT_TRUE(config.area.contains(t.posterior.x.head<2>())) << "scan " << k;
    EXPECT_GE(Eigen::SelfAdjointEigenSolver<Mat4>(t.posterior.P).eigenvalues().minCoeff(), -1e-9);
    lost = lost || t.posterior.P(0, 0) + t.posterior.P(1, 1) > config.delete_trace;
  }
  EXPECT_TRUE(lost);
  const Vec2 mean = tracker.targets()[0].posterior.x.head<2>();
  const Vec2 person = mean + Vec2(30.0, 0.0).cwiseMin(config.area.hi - mean);
  const Mat2 R = 0.3 * Mat2::Identity();
  RandomStream rng(5, "jipda_test_reacquire");
  int held_at = 0;
  for (int k = 1; k <= 10 && held_at == 0; ++k) {
    sensing::Scan scan;
    scan.observations.push_back(targetObservation(person + rng.gaussian(R), R));
    tracker.predict(kDt);
    tracker.update(scan, discFootprint(person, 10.0), OcclusionMap());
    tracker.mergeDuplicates();
    tracker.deleteStale();
    ASSERT_EQ(tracker.targets().size(), 1u) << "scan " << k << ": a birth beside the lost track";
    const TargetGaussian& g = tracker.targets()[0].posterior;
    if ((g.x.head<2>() - person).norm() < 1.0 && g.P(0, 0) + g.P(1, 1) < 1.0) held_at = k;
  }
  EXPECT_GT(held_at, 0) << "not held again within 10 scans";
  EXPECT_EQ(tracker.diagnostics().births, 0);
}

// A target walking at (1, 0.5) m/s, measured every scan with R = 0.3 I; step() runs one scan.
struct Walk {
  RandomStream rng{7, "jipda_test_walk"};
  Vec2 truth = Vec2(0.0, 0.0);
  Vec2 velocity = Vec2(1.0, 0.5);
  sensing::Scan next() {
    truth += kDt * velocity;
    sensing::Scan scan;
    const Mat2 R = 0.3 * Mat2::Identity();
    scan.observations.push_back(targetObservation(truth + rng.gaussian(R), R));
    return scan;
  }
};

TEST(Jipda, TwoTracksOnOneTargetMergeWithinFiveScans) {
  // Two confirmed tracks 1.5 m apart on one target share its measurements; the track-to-track
  // distance passes merge_gate from the first scan, so they merge at scan merge_scans = 3.
  TrackingConfig config;
  Tracker tracker(0, config);
  addUnknown(tracker, {unknownTrack(0, Vec4(0.0, 0.0, 1.0, 0.5), Mat4::Identity()),
                       unknownTrack(1, Vec4(1.5, 0.0, 1.0, 0.5), Mat4::Identity())});
  const sensing::Footprint footprint = discFootprint(Vec2::Zero(), 100.0);
  Walk walk;
  int merged_at = 0;
  for (int k = 1; k <= 5 && merged_at == 0; ++k) {
    tracker.predict(kDt);
    tracker.update(walk.next(), footprint, OcclusionMap());
    tracker.mergeDuplicates();
    tracker.deleteStale();
    if (tracker.targets().size() == 1) merged_at = k;
  }
  ASSERT_GT(merged_at, 0) << "not merged within 5 scans";
  EXPECT_EQ(merged_at, config.merge_scans);
  EXPECT_EQ(tracker.diagnostics().merges, 1);
  EXPECT_EQ(tracker.targets()[0].status, TrackStatus::confirmed);
  EXPECT_NEAR(tracker.targets()[0].posterior.x(0), walk.truth.x(), 1.0);
}

TEST(Jipda, TwoKnownPeopleOnOneSpotAreNeverMerged) {
  // The same two tracks as above, but both pre-seeded: the scenario says they are two people.
  TrackingConfig config;
  Tracker tracker(0, config);
  tracker.preseed(0, 1, Vec4(0.0, 0.0, 1.0, 0.5));
  tracker.preseed(1, 1, Vec4(1.5, 0.0, 1.0, 0.5));
  const sensing::Footprint footprint = discFootprint(Vec2::Zero(), 100.0);
  Walk walk;
  for (int k = 1; k <= 10; ++k) {
    tracker.predict(kDt);
    tracker.update(walk.next(), footprint, OcclusionMap());
    tracker.mergeDuplicates();
    tracker.deleteStale();
  }
  EXPECT_EQ(tracker.targets().size(), 2u);
  EXPECT_EQ(tracker.diagnostics().merges, 0);
}

// Two people who walk side by side 1 m apart, unseen for 10 s (their tracks' P grows far past
// the duplicate test's certainty), then cross under that covariance while a UAV sees them both:
// two detections in each scan, so never one pair updated by one detection; never merged. Under
// the old test (Mahalanobis with P_a + P_b alone) the uncertain pair would pass it.
TEST(Jipda, TwoPeopleWhoCrossUnderLargeCovarianceAreNotMerged) {
  TrackingConfig config;
  Tracker tracker(0, config);
  addUnknown(tracker, {unknownTrack(0, Vec4(0.0, 0.0, 1.0, 0.0), Mat4::Identity()),
                       unknownTrack(1, Vec4(0.0, 1.0, 1.0, 0.0), Mat4::Identity())});
  const sensing::Footprint nowhere = discFootprint(Vec2(-1000.0, 0.0), 5.0);
  for (int k = 0; k < 50; ++k) {  // 10 s unseen
    tracker.predict(kDt);
    tracker.update(sensing::Scan{}, nowhere, OcclusionMap());
    tracker.mergeDuplicates();
  }
  ASSERT_EQ(tracker.targets().size(), 2u);
  const TargetGaussian& a = tracker.targets()[0].posterior;
  const TargetGaussian& b = tracker.targets()[1].posterior;
  ASSERT_GT(a.P(0, 0) + a.P(1, 1), 2.0 * config.merge_distance * config.merge_distance);
  ASSERT_LE(trackDistance(a, b), config.merge_gate);  // the old test alone would pass them
  RandomStream rng(9, "jipda_test_cross");
  Vec2 p(10.0, 0.0), q(10.0, 1.0);
  const Mat2 R = 0.3 * Mat2::Identity();
  for (int k = 0; k < 30; ++k) {  // 6 s: p keeps east, q turns south-east and crosses p's line
    p += kDt * Vec2(1.0, 0.0);
    q += kDt * Vec2(1.0, -0.3);
    sensing::Scan scan;
    scan.observations.push_back(targetObservation(p + rng.gaussian(R), R));
    scan.observations.push_back(targetObservation(q + rng.gaussian(R), R));
    tracker.predict(kDt);
    tracker.update(scan, discFootprint(p, 30.0), OcclusionMap());
    tracker.mergeDuplicates();
    ASSERT_EQ(tracker.targets().size(), 2u) << "scan " << k;
  }
  EXPECT_EQ(tracker.diagnostics().merges, 0);
}

TEST(Jipda, TwoTargetsPassingEachOtherAreNotMerged) {
  // Two targets cross 2 m apart at 2 m/s relative speed: their positions are close for a few
  // scans but their velocities are not, so the 4-D test fails and both tracks stay.
  TrackingConfig config;
  Tracker tracker(0, config);
  tracker.preseed(0, 1, Vec4(-4.0, 0.0, 1.0, 0.0));
  tracker.preseed(1, 1, Vec4(4.0, 2.0, -1.0, 0.0));
  const sensing::Footprint footprint = discFootprint(Vec2::Zero(), 100.0);
  RandomStream rng(3, "jipda_test_crossing");
  Vec2 a(-4.0, 0.0), b(4.0, 2.0);
  const Mat2 R = 0.1 * Mat2::Identity();
  for (int k = 0; k < 40; ++k) {
    a += kDt * Vec2(1.0, 0.0);
    b += kDt * Vec2(-1.0, 0.0);
    sensing::Scan scan;
    scan.observations.push_back(targetObservation(a + rng.gaussian(R), R));
    scan.observations.push_back(targetObservation(b + rng.gaussian(R), R));
    tracker.predict(kDt);
    tracker.update(scan, footprint, OcclusionMap());
    tracker.mergeDuplicates();
    tracker.deleteStale();
    ASSERT_NE(find(tracker, {-1, 0}), nullptr) << "scan " << k;
    ASSERT_NE(find(tracker, {-1, 1}), nullptr) << "scan " << k;
  }
  EXPECT_EQ(tracker.diagnostics().merges, 0);
}

}  // namespace
}  // namespace canopy::agents::tracking
