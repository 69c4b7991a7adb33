// The fusion's result on a recorded case: a closed loop of five UAVs on a line with limited range
// and lost messages, targets and trees, each agent with the toy tracker. Every list after every
// step is hashed; the hashes were recorded from the implementation that rewrote the agents' lists
// in place through pointers (main 48c1a31), so a change of the fusion's data flow that changes a
// bit fails here.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>

#include "agents/fusion/team_fusion.h"
#include "fusion_test_support.h"

namespace canopy::agents::fusion {
namespace {

using test::Team;
using test::trackLocally;

template <typename T>
void appendBytes(std::string& out, const T& value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

template <int N>
void appendGaussian(std::string& out, const Gaussian<N>& g) {
  for (int r = 0; r < N; ++r) appendBytes(out, g.x(r));
  for (int r = 0; r < N; ++r) {
    for (int c = 0; c < N; ++c) appendBytes(out, g.P(r, c));
  }
}

template <int N>
void appendList(std::string& out, const std::vector<tracking::Track<N>>& tracks) {
  appendBytes(out, tracks.size());
  for (const tracking::Track<N>& t : tracks) {
    appendBytes(out, t.key.origin);
    appendBytes(out, t.key.serial);
    appendBytes(out, t.label);
    appendBytes(out, static_cast<int>(t.status));
    appendBytes(out, t.scans);
    appendBytes(out, t.hits);
    appendBytes(out, t.expected_misses);
    appendBytes(out, t.detected);
    appendGaussian(out, t.prior);
    appendGaussian(out, t.posterior);
  }
}

void appendDiagnostics(std::string& out, const FusionDiagnostics& d) {
  for (const long count :
       {d.steps, d.messages, d.lost_messages, d.remembered_matches, d.new_matches,
        d.refused_matches, d.adoptions, d.rekeys, d.numerical_failures}) {
    appendBytes(out, count);
  }
}

/// FNV-1a of every agent's lists after each of 60 fused steps, then of the diagnostics.
std::uint64_t closedLoopHash(FusionMethod method) {
  constexpr int kAgents = 5;
  Team team(kAgents);
  for (int i = 0; i < kAgents; ++i) team.positions[i] = Vec2(20.0 + 40.0 * i, 30.0);
  RandomStream layout(5, "test.fusion_golden.layout");
  test::ToyScene scene = test::toyScene(layout, 8, 10, 200.0);
  std::vector<RandomStream> sensing;
  std::vector<int> serials(kAgents, 0);
  for (int i = 0; i < kAgents; ++i) sensing.emplace_back(5, "test.fusion_golden.sensing", i);

  FusionConfig config;
  config.method = method;
  config.rounds = 3;
  config.comm_range = 50.0;
  config.comm_drop = 0.2;
  TeamFusion fusion(config, kAgents, 5);
  std::string bytes;
  for (int step = 0; step < 60; ++step) {
    scene.advance();
    for (int i = 0; i < kAgents; ++i) {
      trackLocally(team.targets[i], team.positions[i], scene.targets, sensing[i], i, serials[i]);
      trackLocally(team.trees[i], team.positions[i], scene.trees, sensing[i], i, serials[i]);
    }
    team.fuse(fusion);
    for (int i = 0; i < kAgents; ++i) {
      appendList(bytes, team.targets[i]);
      appendList(bytes, team.trees[i]);
    }
  }
  appendDiagnostics(bytes, fusion.diagnostics());
  EXPECT_GT(fusion.diagnostics().adoptions, 0);
  EXPECT_GT(fusion.diagnostics().lost_messages, 0);
  return fnv1a64(bytes);
}

TEST(FusionGolden, CiGivesTheRecordedResult) {
  EXPECT_EQ(closedLoopHash(FusionMethod::ci), 0x6396ac90a49e0c93ULL);
}

TEST(FusionGolden, HcmciGivesTheRecordedResult) {
  EXPECT_EQ(closedLoopHash(FusionMethod::hcmci), 0x266cd8037b1a07d4ULL);
}

TEST(FusionGolden, ObserverAverageGivesTheRecordedResult) {
  EXPECT_EQ(closedLoopHash(FusionMethod::observer_average), 0x7be5bfb42fc617feULL);
}

}  // namespace
}  // namespace canopy::agents::fusion
