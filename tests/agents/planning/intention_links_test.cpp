#include "agents/planning/intention_links.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace canopy::agents::planning {
namespace {

std::vector<UavState> uavsAt(std::vector<Vec2> positions) {
  std::vector<UavState> uavs(positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i) uavs[i].position = positions[i];
  return uavs;
}

IntentionMessage planOf(int from, int epoch) {
  IntentionMessage m{from, from, epoch, hoverPlan(2)};
  m.plan.velocities[0] = Vec2(from, epoch);  // tells the messages apart
  return m;
}

// Planning every step (one step per epoch): a message sent at epoch e with latency k is held
// from epoch e + k on, never before.
TEST(IntentionLinks, LatencyOfKStepsDelaysEachMessageByExactlyKSteps) {
  for (const int k : {0, 1, 3}) {
    IntentionLinks links(LinkConfig{INFINITY, 0.0, k, 1}, 2, 1);
    const std::vector<UavState> uavs = uavsAt({{0, 0}, {5, 0}});
    for (int epoch = 0; epoch < 10; ++epoch) {
      links.beginEpoch(epoch, uavs);
      links.send(planOf(0, epoch));
      // Held once this epoch's message is sent: the message of epoch − k (none before epoch k).
      ASSERT_EQ(links.latest(1, 0).epoch, epoch >= k ? epoch - k : -1) << "k " << k;
      if (epoch >= k) {
        EXPECT_EQ(links.latest(1, 0).plan.velocities[0], Vec2(0, epoch - k));
      }
    }
    EXPECT_EQ(links.counts().sent, 10);
    EXPECT_EQ(links.counts().lost, 0);
    EXPECT_EQ(links.counts().late, k > 0 ? 10 - k : 0);  // the last k are still in flight
  }
}

// Planning every 5 steps (1 s epochs, 0.2 s steps): a latency of 1–5 steps is read one epoch
// later, 6–10 steps two epochs later.
TEST(IntentionLinks, ALatencyInsideAnEpochIsReadAtTheNextEpoch) {
  for (const auto& [k, epochs] : std::vector<std::pair<int, int>>{{1, 1}, {5, 1}, {6, 2}, {10, 2}}) {
    IntentionLinks links(LinkConfig{INFINITY, 0.0, k, 5}, 2, 1);
    const std::vector<UavState> uavs = uavsAt({{0, 0}, {5, 0}});
    links.beginEpoch(0, uavs);
    links.send(planOf(0, 0));
    for (int epoch = 1; epoch <= epochs; ++epoch) {
      links.beginEpoch(epoch, uavs);
      EXPECT_EQ(links.latest(1, 0).epoch, epoch == epochs ? 0 : -1) << "k " << k;
    }
  }
}

TEST(IntentionLinks, LossOfOneDeliversNothingAndCountsEveryMessageLost) {
  IntentionLinks links(LinkConfig{INFINITY, 1.0, 0, 1}, 3, 9);
  const std::vector<UavState> uavs = uavsAt({{0, 0}, {5, 0}, {10, 0}});
  for (int epoch = 0; epoch < 4; ++epoch) {
    links.beginEpoch(epoch, uavs);
    for (int i = 0; i < 3; ++i) links.send(planOf(i, epoch));
  }
  for (int r = 0; r < 3; ++r) {
    for (int a = 0; a < 3; ++a) EXPECT_EQ(links.latest(r, a).epoch, -1);
  }
  EXPECT_EQ(links.counts().sent, 4 * 3 * 2);  // to both teammates, every epoch
  EXPECT_EQ(links.counts().lost, 4 * 3 * 2);
}

// Within range there is a link; 30 m apart with a 10 m range there is none (nothing sent).
TEST(IntentionLinks, OnlyTeammatesWithinRangeHearAMessage) {
  IntentionLinks links(LinkConfig{10.0, 0.0, 0, 1}, 3, 1);
  links.beginEpoch(0, uavsAt({{0, 0}, {10, 0}, {30, 0}}));  // 0–1: 10 m (in range); 0–2: 30 m
  links.send(planOf(0, 0));
  EXPECT_EQ(links.latest(1, 0).epoch, 0);
  EXPECT_EQ(links.latest(2, 0).epoch, -1);
  EXPECT_EQ(links.counts().sent, 1);
  EXPECT_EQ(links.counts().lost, 0);
}

// A sent message is lost with probability drop, independently: 20 000 messages at drop 0.3
// lose 0.3 ± 4σ, σ = √(0.3·0.7/20 000) = 0.0032.
TEST(IntentionLinks, DropIsTheFractionOfMessagesLost) {
  IntentionLinks links(LinkConfig{INFINITY, 0.3, 0, 1}, 2, 5);
  const std::vector<UavState> uavs = uavsAt({{0, 0}, {1, 0}});
  for (int epoch = 0; epoch < 10000; ++epoch) {
    links.beginEpoch(epoch, uavs);
    links.send(planOf(0, epoch));
    links.send(planOf(1, epoch));
  }
  ASSERT_EQ(links.counts().sent, 20000);
  EXPECT_NEAR(static_cast<double>(links.counts().lost) / 20000.0, 0.3, 4 * std::sqrt(0.3 * 0.7 / 20000));
}

// Sent to one agent: the others hear nothing of it (the centralised leader's orders).
TEST(IntentionLinks, AMessageToOneAgentReachesOnlyIt) {
  IntentionLinks links(LinkConfig{}, 3, 1);
  links.beginEpoch(0, uavsAt({{0, 0}, {1, 0}, {2, 0}}));
  IntentionMessage order{0, 2, 0, hoverPlan(2)};
  links.send(order, 2);
  EXPECT_EQ(links.latest(2, 2).epoch, 0);
  EXPECT_EQ(links.latest(1, 2).epoch, -1);
  EXPECT_EQ(links.counts().sent, 1);
}

}  // namespace
}  // namespace canopy::agents::planning
