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
  test::ToyScene scene = test::toyScene(motion, 8, 0, 240.0);
  std::vector<RandomStream> sensing;
  std::vector<int> serials(n, 0);
  for (int i = 0; i < n; ++i) sensing.emplace_back(3, "test.closed_loop.sensing", i);

  FusionConfig config;
  config.comm_range = 50.0;
  config.comm_drop = 0.2;
  TeamFusion fusion(config, n, 3);
  for (int step = 0; step < 100; ++step) {
    scene.advance();
    for (int i = 0; i < n; ++i) {
      trackLocally(team.targets[i], team.positions[i], scene.targets, sensing[i], i, serials[i]);
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

// With a pool the clusters' consensus runs in parts side by side (TeamFusion::setPool); the
// fused lists and counters must be those of one part, bit for bit, for every method. The team is
// large enough (12 agents, 30 targets, 40 trees) that every part holds clusters.
template <int N>
void expectSameTracks(const std::vector<std::vector<tracking::Track<N>>>& a,
                      const std::vector<std::vector<tracking::Track<N>>>& b, int step) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a[i].size(), b[i].size()) << "agent " << i << ", step " << step;
    for (std::size_t k = 0; k < a[i].size(); ++k) {
      EXPECT_EQ(a[i][k].key, b[i][k].key);
      EXPECT_EQ(a[i][k].posterior.x, b[i][k].posterior.x) << "agent " << i << ", step " << step;
      EXPECT_EQ(a[i][k].posterior.P, b[i][k].posterior.P) << "agent " << i << ", step " << step;
      EXPECT_EQ(a[i][k].existence, b[i][k].existence);
      EXPECT_EQ(a[i][k].status, b[i][k].status);
    }
  }
}

TEST(TeamFusion, ConsensusInPartsOnAPoolGivesTheSameListsBitForBit) {
  const int n = 12;
  for (const FusionMethod method :
       {FusionMethod::ci, FusionMethod::hcmci, FusionMethod::observer_average}) {
    Team alone(n), pooled(n);
    RandomStream layout(5, "test.parts.layout");
    test::ToyScene scene = test::toyScene(layout, 30, 40, 480.0);
    for (int i = 0; i < n; ++i) {
      alone.positions[i] = pooled.positions[i] = Vec2(20.0 + 40.0 * i, 30.0);  // a path graph
    }
    FusionConfig config;
    config.method = method;
    config.rounds = 3;
    config.comm_range = 50.0;
    config.comm_drop = 0.2;
    TeamFusion one(config, n, 9), parts(config, n, 9);
    TaskPool pool(3);
    parts.setPool(&pool);
    std::vector<RandomStream> sensing;
    for (int i = 0; i < n; ++i) sensing.emplace_back(9, "test.parts.sensing", i);
    std::vector<int> serials(n, 0);
    for (int step = 0; step < 40; ++step) {
      scene.advance();
      for (int i = 0; i < n; ++i) {
        // Each agent's local tracking, copied to both teams' lists before fusion.
        trackLocally(alone.targets[i], alone.positions[i], scene.targets, sensing[i], i,
                     serials[i]);
        trackLocally(alone.trees[i], alone.positions[i], scene.trees, sensing[i], i, serials[i]);
        pooled.targets[i] = alone.targets[i];
        pooled.trees[i] = alone.trees[i];
      }
      alone.fuse(one);
      pooled.fuse(parts);
      expectSameTracks(alone.targets, pooled.targets, step);
      expectSameTracks(alone.trees, pooled.trees, step);
      if (::testing::Test::HasFailure()) return;
    }
    EXPECT_GT(one.diagnostics().adoptions, 0);
    EXPECT_EQ(one.diagnostics().messages, parts.diagnostics().messages);
    EXPECT_EQ(one.diagnostics().numerical_failures, parts.diagnostics().numerical_failures);
    EXPECT_EQ(one.diagnostics().new_matches, parts.diagnostics().new_matches);
  }
}

}  // namespace
}  // namespace canopy::agents::fusion
