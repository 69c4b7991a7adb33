// A small closed loop: UAVs on a line with limited range, each with a toy local tracker (predict,
// nearest-track update, birth), fused every step with losses. Checks the invariants TeamFusion
// promises whatever the tracks do, then that a fully connected team ends in agreement.
#include "agents/fusion/team_fusion.h"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <algorithm>
#include <map>
#include <set>

#include "agents/fusion/small_cholesky.h"
#include "fusion_test_support.h"

namespace canopy::agents::fusion {
namespace {

using test::Team;

constexpr double kDt = 0.2;              // s
constexpr double kFootprint = 35.0;      // m, disc radius around each UAV
constexpr double kMeasurementVar = 0.5;  // m²

/// NCV prediction (paper eq. 4), σ_a = 1 m/s².
TargetGaussian predict(const TargetGaussian& g) {
  Mat4 F = Mat4::Identity();
  F(0, 2) = F(1, 3) = kDt;
  Mat4 Q = Mat4::Zero();
  const double q4 = std::pow(kDt, 4) / 4, q3 = std::pow(kDt, 3) / 2, q2 = kDt * kDt;
  for (int a = 0; a < 2; ++a) {
    Q(a, a) = q4;
    Q(a, a + 2) = Q(a + 2, a) = q3;
    Q(a + 2, a + 2) = q2;
  }
  return {F * g.x, F * g.P * F.transpose() + Q};
}

TargetGaussian update(const TargetGaussian& g, const Vec2& z) {
  const Mat2 S = g.P.topLeftCorner<2, 2>() + kMeasurementVar * Mat2::Identity();
  const Mat42 K = g.P.leftCols<2>() * S.inverse();
  TargetGaussian out{g.x + K * (z - g.x.head<2>()), g.P - K * S * K.transpose()};
  out.P = 0.5 * (out.P + out.P.transpose());
  return out;
}

/// One agent's toy tracking step: predict all, update the nearest gated track per detection,
/// birth a tentative track otherwise, confirm on the second hit.
void trackLocally(std::vector<tracking::TargetTrack>& tracks, const Vec2& uav,
                  const std::vector<Vec2>& targets, RandomStream& rng, int agent, int& serial) {
  for (auto& track : tracks) {
    track.prior = predict(track.posterior);
    track.posterior = track.prior;
    track.detected = false;
  }
  for (const Vec2& target : targets) {
    if ((target - uav).norm() > kFootprint) continue;
    const Vec2 z = target + std::sqrt(kMeasurementVar) * Vec2(rng.normal(), rng.normal());
    tracking::TargetTrack* best = nullptr;
    double best_d2 = 9.21;
    for (auto& track : tracks) {
      const Mat2 S = track.prior.P.topLeftCorner<2, 2>() + kMeasurementVar * Mat2::Identity();
      const Vec2 nu = z - track.prior.x.head<2>();
      const double d2 = nu.dot(S.inverse() * nu);
      if (d2 < best_d2) {
        best_d2 = d2;
        best = &track;
      }
    }
    if (best) {
      best->posterior = update(best->posterior, z);
      best->detected = true;
      if (++best->hits >= 2) best->status = tracking::TrackStatus::confirmed;
    } else {
      Mat4 P = Mat4::Identity();
      P.topLeftCorner<2, 2>() *= kMeasurementVar;
      tracks.push_back(test::makeTrack<4>({agent, serial++}, Vec4(z.x(), z.y(), 0, 0), P, 1,
                                          /*confirmed=*/false));
      tracks.back().hits = 1;
      tracks.back().detected = true;
    }
  }
}

void expectInvariants(const Team& team, int step) {
  std::map<std::pair<int, int>, sensing::LabelId> label_of;
  for (std::size_t i = 0; i < team.targets.size(); ++i) {
    std::set<std::pair<int, int>> keys;
    for (const auto& track : team.targets[i]) {
      const std::pair<int, int> key{track.key.origin, track.key.serial};
      EXPECT_TRUE(keys.insert(key).second) << "agent " << i << " holds a key twice, step " << step;
      EXPECT_EQ(label_of.emplace(key, track.label).first->second, track.label)
          << "one key, two labels";
      EXPECT_TRUE(track.posterior.x.allFinite());
      EXPECT_TRUE(SmallCholesky<4>(track.posterior.P).ok()) << "step " << step;
    }
  }
}

TEST(TeamFusion, ClosedLoopKeepsItsInvariantsAndAConnectedTeamAgrees) {
  const int n = 6;
  Team team(n);
  for (int i = 0; i < n; ++i) team.positions[i] = Vec2(20.0 + 40.0 * i, 30.0);  // a path graph
  RandomStream motion(3, "test.closed_loop.motion");
  std::vector<Vec2> targets, velocities;
  for (int t = 0; t < 8; ++t) {
    targets.emplace_back(motion.uniform(0.0, 240.0), motion.uniform(10.0, 50.0));
    velocities.emplace_back(motion.uniform(-2.0, 2.0), motion.uniform(-0.5, 0.5));
  }
  std::vector<RandomStream> sensing;
  std::vector<int> serials(n, 0);
  for (int i = 0; i < n; ++i) sensing.emplace_back(3, "test.closed_loop.sensing", i);

  FusionConfig config;
  config.comm_range = 50.0;
  config.comm_drop = 0.2;
  TeamFusion fusion(config, n, 3);
  for (int step = 0; step < 100; ++step) {
    for (std::size_t t = 0; t < targets.size(); ++t) targets[t] += kDt * velocities[t];
    for (int i = 0; i < n; ++i) {
      trackLocally(team.targets[i], team.positions[i], targets, sensing[i], i, serials[i]);
    }
    team.fuse(fusion);
    expectInvariants(team, step);
  }
  EXPECT_GT(fusion.diagnostics().adoptions, 0);
  EXPECT_GT(fusion.diagnostics().remembered_matches, 0);
  EXPECT_EQ(fusion.diagnostics().numerical_failures, 0);

  // Everyone in range of everyone, no losses, no new measurements: one step shares every
  // confirmed track, the next leaves all agents with the same estimate of each.
  FusionConfig complete;
  TeamFusion settle(complete, n, 3);
  for (int step = 0; step < 2; ++step) team.fuse(settle);
  std::map<std::pair<int, int>, TargetGaussian> reference;  // agent 0's tracks by key
  for (const auto& track : team.targets[0]) {
    reference[{track.key.origin, track.key.serial}] = track.posterior;
  }
  std::set<std::pair<int, int>> confirmed;  // keys confirmed anywhere
  for (const auto& list : team.targets) {
    for (const auto& track : list) {
      if (track.status == tracking::TrackStatus::confirmed) {
        confirmed.insert({track.key.origin, track.key.serial});
      }
    }
  }
  ASSERT_FALSE(confirmed.empty());
  for (int i = 0; i < n; ++i) {
    for (const auto& key : confirmed) {
      const auto held = std::find_if(team.targets[i].begin(), team.targets[i].end(),
                                     [&](const tracking::TargetTrack& track) {
                                       return track.key == TrackKey{key.first, key.second};
                                     });
      ASSERT_NE(held, team.targets[i].end()) << "agent " << i << " lacks a confirmed track";
      const TargetGaussian& expected = reference.at(key);
      EXPECT_LT((held->posterior.x - expected.x).norm(), 1e-9);
      EXPECT_LT((held->posterior.P - expected.P).norm(), 1e-9);
    }
  }
}

}  // namespace
}  // namespace canopy::agents::fusion
