// Consensus messages with a latency of k steps (fusion.comm_latency): a receiver fuses what its
// neighbour held k steps before, predicted to now, and nothing before the first one is due.
#include <gtest/gtest.h>

#include "agents/fusion/team_fusion.h"
#include "fusion_test_support.h"

namespace canopy::agents::fusion {
namespace {

using test::Team;

// Agent 0 holds one confirmed track whose mean at step s is (s, 0) m moving at (1, 0) m/s with
// P = I₄; agent 1 holds nothing of its own. dt = 0.2 s, σ_a = 1 m/s².
tracking::TargetTrack trackAtStep(int s) {
  tracking::TargetTrack track =
      test::makeTrack<4>(TrackKey{0, 1}, Vec4(s, 0.0, 1.0, 0.0), Mat4::Identity(), 1, true);
  return track;
}

TEST(ConsensusLatency, EachMessageArrivesExactlyKStepsLaterPredictedToNow) {
  for (const int k : {0, 1, 3}) {
    FusionConfig config;
    config.comm_latency = k;
    TeamFusion fusion(config, 2, 1, 0.2, 1.0);
    for (int s = 0; s < 6; ++s) {
      Team team(2);
      team.targets[0] = {trackAtStep(s)};
      team.fuse(fusion);
      if (s < k) {
        EXPECT_TRUE(team.targets[1].empty()) << "k = " << k << ", step " << s;
        continue;
      }
      ASSERT_EQ(team.targets[1].size(), 1u) << "k = " << k << ", step " << s;
      // The track agent 0 sent at step s − k, predicted over τ = k·dt: the mean (s − k + τ, 0),
      // per axis P_pos = 1 + τ² + σ_a² τ⁴/4 (F P Fᵀ + Q with P = I).
      const double tau = 0.2 * k;
      const TargetGaussian& got = team.targets[1][0].posterior;
      EXPECT_NEAR(got.x(0), s - k + tau, 1e-12) << "k = " << k << ", step " << s;
      EXPECT_NEAR(got.x(1), 0.0, 1e-12);
      EXPECT_NEAR(got.P(0, 0), 1.0 + tau * tau + tau * tau * tau * tau / 4.0, 1e-12);
      // Agent 0 received nothing from agent 1 and keeps its own track as it was.
      ASSERT_EQ(team.targets[0].size(), 1u);
      EXPECT_NEAR(team.targets[0][0].posterior.x(0), s, 1e-12);
    }
    // Counted when due: 2 directed links × 5 rounds a step, from step k on; all late when k > 0.
    const FusionDiagnostics& d = fusion.diagnostics();
    EXPECT_EQ(d.messages, 10 * (6 - k)) << "k = " << k;
    EXPECT_EQ(d.lost_messages, 0);
    EXPECT_EQ(d.late_messages, k > 0 ? 10 * (6 - k) : 0) << "k = " << k;
  }
}

TEST(ConsensusLatency, LateMessagesAreLostLikeAnyOther) {
  FusionConfig config;
  config.comm_latency = 2;
  config.comm_drop = 1.0;
  TeamFusion fusion(config, 2, 1, 0.2, 1.0);
  for (int s = 0; s < 5; ++s) {
    Team team(2);
    team.targets[0] = {trackAtStep(s)};
    team.fuse(fusion);
    // The association exchange is reliable (TeamFusion), so a copy is adopted when due, but every
    // consensus message is lost: no information beyond the copy.
    EXPECT_EQ(team.targets[1].empty(), s < 2) << "step " << s;
  }
  EXPECT_EQ(fusion.diagnostics().messages, 30);
  EXPECT_EQ(fusion.diagnostics().lost_messages, 30);
  EXPECT_EQ(fusion.diagnostics().late_messages, 0);
}

}  // namespace
}  // namespace canopy::agents::fusion
