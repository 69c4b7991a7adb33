// A small closed loop: UAVs on a line with limited range, each with a toy local tracker
// (fusion_test_support.h), fused every step with losses. Checks the invariants TeamFusion
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
using test::trackLocally;

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
    for (std::size_t t = 0; t < targets.size(); ++t) targets[t] += test::kToyDt * velocities[t];
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
