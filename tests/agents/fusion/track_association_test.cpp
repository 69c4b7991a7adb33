// Association through the public entry point: keys, labels, gating, memory, adoption, range.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "agents/fusion/team_fusion.h"
#include "fusion_test_support.h"

namespace canopy::agents::fusion {
namespace {

using test::Mat3;
using test::targetAt;
using test::Team;
using test::Vec3;

const tracking::TargetTrack* findKey(const std::vector<tracking::TargetTrack>& list, TrackKey key) {
  const auto it = std::find_if(list.begin(), list.end(),
                               [&](const tracking::TargetTrack& t) { return t.key == key; });
  return it == list.end() ? nullptr : &*it;
}

void expectUniqueKeys(const std::vector<tracking::TargetTrack>& list) {
  std::set<std::pair<int, int>> keys;
  for (const auto& track : list) {
    EXPECT_TRUE(keys.insert({track.key.origin, track.key.serial}).second) << "duplicate key";
  }
}

TEST(TrackAssociation, MatchedTracksAdoptTheSmallerKey) {
  Team team(2);
  team.targets[0] = {targetAt({1, 7}, 10.0, 10.0)};
  team.targets[1] = {targetAt({0, 9}, 10.5, 9.8)};
  TeamFusion fusion(FusionConfig{}, 2, 1);
  for (int step = 0; step < 3; ++step) {
    team.fuse(fusion);
    for (int i = 0; i < 2; ++i) {
      ASSERT_EQ(team.targets[i].size(), 1u);
      EXPECT_EQ(team.targets[i][0].key, (TrackKey{0, 9}));
    }
  }
  EXPECT_EQ(fusion.diagnostics().new_matches, 1);         // the first step: by assignment
  EXPECT_EQ(fusion.diagnostics().remembered_matches, 2);  // then by the shared key
}

TEST(TrackAssociation, KeysConvergeAlongAChainOfNeighbours) {
  // 0 — 1 — 2 on a line (range 15 m): 0 and 2 never talk, yet all end with 2's key.
  Team team(3);
  team.positions = {{0, 0}, {10, 0}, {20, 0}};
  team.targets[0] = {targetAt({0, 4}, 50.0, 50.0)};
  team.targets[1] = {targetAt({1, 0}, 50.3, 50.0)};
  team.targets[2] = {targetAt({-1, 2}, 50.6, 50.0)};
  FusionConfig config;
  config.comm_range = 15.0;
  TeamFusion fusion(config, 3, 1);
  team.fuse(fusion);
  for (int i = 0; i < 3; ++i) {
    ASSERT_EQ(team.targets[i].size(), 1u);
    EXPECT_EQ(team.targets[i][0].key, (TrackKey{-1, 2}));
  }
}

TEST(TrackAssociation, DifferentLabelsAreNeverMatched) {
  Team team(2);
  team.targets[0] = {targetAt({0, 0}, 5.0, 5.0, 1.0, /*label=*/1)};
  team.targets[1] = {targetAt({1, 0}, 5.0, 5.0, 1.0, /*label=*/2)};
  TeamFusion fusion(FusionConfig{}, 2, 1);
  team.fuse(fusion);
  for (int i = 0; i < 2; ++i) {
    ASSERT_EQ(team.targets[i].size(), 2u);  // each adopted the other's, as a separate track
    const auto* human = findKey(team.targets[i], {0, 0});
    const auto* car = findKey(team.targets[i], {1, 0});
    ASSERT_TRUE(human && car);
    EXPECT_EQ(human->label, 1);
    EXPECT_EQ(car->label, 2);
  }
  EXPECT_EQ(fusion.diagnostics().new_matches, 0);
}

TEST(TrackAssociation, NonGatedPairIsNeverMatchedEvenWhenTheAssignmentWouldPreferIt) {
  // Unit position variances, so S = 2I and d² = |Δp|² / 2 (gate 9.21: |Δp| ≤ 4.29 m).
  // A(0,0) B(3,0) of agent 0; C(1,0) D(10,0) of agent 1: d²(A,C) = 0.5, d²(B,C) = 2,
  // d²(A,D) = 50, d²(B,D) = 24.5. A full assignment takes A–C and B–D (25 < 52); B–D is far
  // outside the gate, so only A–C may be matched: B and D stay two targets.
  Team team(2);
  team.targets[0] = {targetAt({0, 0}, 0.0, 0.0), targetAt({0, 1}, 3.0, 0.0)};
  team.targets[1] = {targetAt({1, 0}, 1.0, 0.0), targetAt({1, 1}, 10.0, 0.0)};
  TeamFusion fusion(FusionConfig{}, 2, 1);
  team.fuse(fusion);
  EXPECT_EQ(fusion.diagnostics().new_matches, 1);
  for (int i = 0; i < 2; ++i) {
    ASSERT_EQ(team.targets[i].size(), 3u);
    expectUniqueKeys(team.targets[i]);
    const auto* ac = findKey(team.targets[i], {0, 0});
    const auto* b = findKey(team.targets[i], {0, 1});
    const auto* d = findKey(team.targets[i], {1, 1});
    ASSERT_TRUE(ac && b && d);
    EXPECT_NEAR(ac->posterior.x(0), 0.5, 1e-12);  // CI of equal covariances: the mean
    EXPECT_NEAR(b->posterior.x(0), 3.0, 1e-12);   // untouched by D
    EXPECT_NEAR(d->posterior.x(0), 10.0, 1e-12);  // untouched by B
  }
}

TEST(TrackAssociation, TracksSharingAKeyStayMatchedOverACheaperSwap) {
  // Same keys, positions crossed: K1 (0,0)/(1.6,0) and K2 (2,0)/(0.4,0): keeping keys costs
  // d² = 1.28 + 1.28, swapping only 0.08 + 0.08, but both kept pairs are within the gate.
  Team team(2);
  team.targets[0] = {targetAt({0, 1}, 0.0, 0.0), targetAt({0, 2}, 2.0, 0.0)};
  team.targets[1] = {targetAt({0, 1}, 1.6, 0.0), targetAt({0, 2}, 0.4, 0.0)};
  TeamFusion fusion(FusionConfig{}, 2, 1);
  team.fuse(fusion);
  EXPECT_EQ(fusion.diagnostics().remembered_matches, 2);
  EXPECT_EQ(fusion.diagnostics().new_matches, 0);
  for (int i = 0; i < 2; ++i) {
    ASSERT_EQ(team.targets[i].size(), 2u);
    EXPECT_NEAR(findKey(team.targets[i], {0, 1})->posterior.x(0), 0.8, 1e-12);
    EXPECT_NEAR(findKey(team.targets[i], {0, 2})->posterior.x(0), 1.2, 1e-12);
  }
}

TEST(TrackAssociation, DriftedTracksSharingAKeyAreSplitAndOneIsRekeyed) {
  Team team(2);
  team.targets[0] = {targetAt({-1, 0}, 0.0, 0.0)};
  team.targets[1] = {targetAt({-1, 0}, 100.0, 0.0)};
  TeamFusion fusion(FusionConfig{}, 2, 1);
  team.fuse(fusion);
  EXPECT_EQ(fusion.diagnostics().rekeys, 1);
  // Equal sizes: the cluster holding the lowest agent keeps the key; agent 1's gets {1, −1}.
  for (int i = 0; i < 2; ++i) {
    ASSERT_EQ(team.targets[i].size(), 2u);
    expectUniqueKeys(team.targets[i]);
    EXPECT_NEAR(findKey(team.targets[i], {-1, 0})->posterior.x(0), 0.0, 1e-12);
    EXPECT_NEAR(findKey(team.targets[i], {1, -1})->posterior.x(0), 100.0, 1e-12);
  }
  team.fuse(fusion);  // stable afterwards
  EXPECT_EQ(fusion.diagnostics().rekeys, 1);
  EXPECT_EQ(team.targets[0].size(), 2u);
}

TEST(TrackAssociation, TreeSeenOnlyByOneUavReachesTheOthersMap) {
  Team team(3);
  const Vec3 tree(12.0, -4.0, 2.5);  // centre (m), radius (m)
  const Mat3 P = Vec3(0.3, 0.2, 0.05).asDiagonal();
  team.trees[0] = {test::makeTrack<3>({0, 3}, tree, P, sensing::kTreeLabel)};
  team.trees[2] = {test::makeTrack<3>({2, 0}, Vec3(40.0, 40.0, 1.0), P, sensing::kTreeLabel)};
  TeamFusion fusion(FusionConfig{}, 3, 1);
  team.fuse(fusion);
  for (int i = 1; i < 3; ++i) {
    const auto it =
        std::find_if(team.trees[i].begin(), team.trees[i].end(), [](const tracking::TreeTrack& t) {
          return t.key == TrackKey{0, 3};
        });
    ASSERT_NE(it, team.trees[i].end()) << "UAV" << i + 1;
    EXPECT_EQ(it->label, sensing::kTreeLabel);
    EXPECT_EQ(it->status, tracking::TrackStatus::confirmed);
    EXPECT_TRUE(it->posterior.x.isApprox(tree, 1e-12));
    EXPECT_TRUE(it->posterior.P.isApprox(P, 1e-12));
  }
  EXPECT_EQ(team.trees[1].size(), 2u);  // and UAV3's tree too
  EXPECT_EQ(fusion.diagnostics().adoptions, 4);
}

// UAV1 holds nothing; UAV0 holds people A and B, UAV2 holds A: A's cluster has two members next
// to UAV1, and between them (nodes in agent order: 0's A, 0's B, 2's A) UAV1 is offered B. UAV1
// adopts A once and B once, UAV2 adopts B: three adoptions, two tracks each, every key once,
// step after step. (A cluster offered again by its second member gave UAV1 a second copy of A,
// and such copies multiplied: 16 UAVs over a city held 780 tracks each after 18 s.)
TEST(TrackAssociation, AnAgentNextToSeveralMembersAdoptsTheClusterOnce) {
  Team team(3);
  team.targets[0] = {targetAt({-1, 1}, 10.0, 10.0), targetAt({-1, 2}, 50.0, 50.0)};
  team.targets[2] = {targetAt({-1, 1}, 10.2, 10.0)};
  TeamFusion fusion(FusionConfig{}, 3, 1);
  for (int step = 0; step < 4; ++step) {
    team.fuse(fusion);
    for (int i = 0; i < 3; ++i) {
      ASSERT_EQ(team.targets[i].size(), 2u) << "UAV" << i << ", step " << step;
      expectUniqueKeys(team.targets[i]);
      EXPECT_NE(findKey(team.targets[i], {-1, 1}), nullptr);
      EXPECT_NE(findKey(team.targets[i], {-1, 2}), nullptr);
    }
    if (step == 0) {
      EXPECT_EQ(fusion.diagnostics().adoptions, 3);
    }
  }
}

TEST(TrackAssociation, TentativeTracksAreNotAdopted) {
  Team team(2);
  team.targets[0] = {targetAt({0, 0}, 0.0, 0.0, 1.0, 1, /*confirmed=*/false)};
  TeamFusion fusion(FusionConfig{}, 2, 1);
  team.fuse(fusion);
  EXPECT_TRUE(team.targets[1].empty());
}

TEST(TrackAssociation, AgentsOutOfRangeExchangeNothing) {
  Team team(2);
  team.positions = {{0, 0}, {200, 0}};
  team.targets[0] = {targetAt({0, 0}, 10.0, 10.0, 2.0)};
  team.targets[1] = {targetAt({1, 0}, 10.5, 10.0, 1.0)};
  team.trees[0] = {test::makeTrack<3>({0, 1}, Vec3(1, 2, 3), Mat3::Identity(), 0)};
  const Team before = team;
  FusionConfig config;
  config.comm_range = 50.0;
  TeamFusion fusion(config, 2, 1);
  team.fuse(fusion);
  for (int i = 0; i < 2; ++i) {
    ASSERT_EQ(team.targets[i].size(), before.targets[i].size());
    ASSERT_EQ(team.trees[i].size(), before.trees[i].size());
    for (std::size_t t = 0; t < team.targets[i].size(); ++t) {
      EXPECT_EQ(team.targets[i][t].key, before.targets[i][t].key);
      EXPECT_EQ(team.targets[i][t].posterior.x, before.targets[i][t].posterior.x);
      EXPECT_EQ(team.targets[i][t].posterior.P, before.targets[i][t].posterior.P);
    }
  }
  EXPECT_EQ(fusion.diagnostics().messages, 0);
  EXPECT_EQ(fusion.diagnostics().adoptions, 0);
}

}  // namespace
}  // namespace canopy::agents::fusion
