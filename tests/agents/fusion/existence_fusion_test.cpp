// Existence across the team: CI's log-odds mean and HCMCI's independent evidence, against odds
// multiplied out by hand.
#include <gtest/gtest.h>

#include "agents/fusion/team_fusion.h"
#include "fusion_test_support.h"

namespace canopy::agents::fusion {
namespace {

using test::Team;

// Two agents holding one track each of the same key, with existences r0, r1 (predicted ψ0, ψ1).
Team pair(double r0, double r1, double psi0, double psi1) {
  Team team(2);
  team.targets[0] = {test::targetAt({-1, 0}, 0.0, 0.0)};
  team.targets[1] = {test::targetAt({-1, 0}, 0.1, 0.0)};
  team.targets[0][0].existence = r0;
  team.targets[1][0].existence = r1;
  team.targets[0][0].existence_prior = psi0;
  team.targets[1][0].existence_prior = psi1;
  return team;
}

TEST(ExistenceFusion, CiTakesTheGeometricMeanOfTheOdds) {
  // Odds 9 (r = 0.9) and 1 (r = 0.5): their geometric mean is 3, r = 3 / 4. One round on two
  // agents mixes with weights ½, ½ (Metropolis), so it is exact.
  Team team = pair(0.9, 0.5, 0.95, 0.95);
  FusionConfig config;
  config.rounds = 1;
  TeamFusion fusion(config, 2, 1);
  team.fuse(fusion);
  for (const auto& list : team.targets) EXPECT_NEAR(list.at(0).existence, 0.75, 1e-12);
}

TEST(ExistenceFusion, HcmciMultipliesTheAgentsLikelihoodRatios) {
  // Both predicted ψ = 0.8 (odds 4). Agent 0 saw the target (r = 0.9, odds 9: likelihood ratio
  // 9/4), agent 1 missed it in view (r = 0.5, odds 1: ratio 1/4). Independent evidence:
  // odds 4 · (9/4) · (1/4) = 9/4, r = 9/13.
  Team team = pair(0.9, 0.5, 0.8, 0.8);
  FusionConfig config;
  config.method = FusionMethod::hcmci;
  TeamFusion fusion(config, 2, 1);
  team.fuse(fusion);
  for (const auto& list : team.targets) EXPECT_NEAR(list.at(0).existence, 9.0 / 13.0, 1e-9);
}

TEST(ExistenceFusion, HcmciAgentWithoutEvidenceChangesNothing) {
  // Agent 1 could not see the target (r = ψ): the fused existence is agent 0's.
  Team team = pair(0.99, 0.8, 0.8, 0.8);
  FusionConfig config;
  config.method = FusionMethod::hcmci;
  TeamFusion fusion(config, 2, 1);
  team.fuse(fusion);
  for (const auto& list : team.targets) EXPECT_NEAR(list.at(0).existence, 0.99, 1e-9);
}

}  // namespace
}  // namespace canopy::agents::fusion
