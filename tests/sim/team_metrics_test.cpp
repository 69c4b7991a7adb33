// The team's figures (sim/team_metrics.h) on a snapshot worked by hand: three agents, four people.
#include "sim/team_metrics.h"

#include <gtest/gtest.h>

#include <cmath>

namespace canopy::sim {
namespace {

agents::TrackEstimate track(agents::TrackKey key, const Vec2& p, double variance) {
  agents::TrackEstimate t;
  t.key = key;
  t.belief.x = Vec4(p.x(), p.y(), 0.0, 0.0);
  t.belief.P = variance * Mat4::Identity();
  t.confirmed = true;
  return t;
}

// People at (0, 0), (10, 0), (100, 0), (0, 100).
// Agent 0: {-1,0} at (1, 0), P = I; {-1,1} at (10, 2), P = I.
// Agent 1: {-1,0} at (0, 0.5), P = 0.25 I (tr 0.5: the best copy of {-1,0}); {0,7} at (100, 4), P =
// I. Agent 2: {-1,1} at (10, 1), P = 9 I (nearer the person, but tr 18 > 2: agent 0's copy is the
//          team's); {2,1} at (300, 0), P = I (no person within c = 50 m).
// The team's set: (0, 0.5), (10, 2), (100, 4), (300, 0). Assignment: d² = 0.25, 4, 16 for the
// first three people; (0, 100) has no estimate within c, (300, 0) no person: one missed, one false.
//   OSPA  = sqrt((0.25 + 4 + 16 + 2500 · 1) / 4) = sqrt(630.0625)
//   GOSPA = sqrt(0.25 + 4 + 16 + 2500 / 2 · (1 + 1)) = sqrt(2520.25)
// Held (within 5 m and inside the 99 % ellipse, Δpᵀ P⁻¹ Δp ≤ 9.21): (0, 0): 0.25 / 0.25 = 1, yes;
// (10, 0): 4 / 1 = 4, yes; (100, 0): 16 / 1 = 16, no; (0, 100): no. Two held.
TEST(TeamMetrics, ThreeAgentsFourPeopleByHand) {
  const std::vector<Vec2> people{Vec2(0, 0), Vec2(10, 0), Vec2(100, 0), Vec2(0, 100)};
  std::vector<agents::AgentBelief> beliefs(3);
  beliefs[0].tracks = {track({-1, 0}, Vec2(1, 0), 1.0), track({-1, 1}, Vec2(10, 2), 1.0)};
  beliefs[1].tracks = {track({-1, 0}, Vec2(0, 0.5), 0.25), track({0, 7}, Vec2(100, 4), 1.0)};
  beliefs[2].tracks = {track({-1, 1}, Vec2(10, 1), 9.0), track({2, 1}, Vec2(300, 0), 1.0)};
  TeamMetrics metrics;
  std::vector<char> held;
  const TeamFigures f = metrics.compute(people, beliefs, &held);
  EXPECT_EQ(f.estimates, 4);
  EXPECT_NEAR(f.ospa, std::sqrt(630.0625), 1e-12);
  EXPECT_NEAR(f.gospa, std::sqrt(2520.25), 1e-12);
  EXPECT_EQ(f.held, 2);
  EXPECT_EQ(held, (std::vector<char>{1, 1, 0, 0}));
}

// Copies of one key with equal traces: the lower agent's is the team's, whatever the key order in
// the agents' lists; a later copy replaces it only with a strictly smaller trace. One person at
// (0, 0) and one key, so OSPA is the distance to the copy kept (one estimate, d < c).
TEST(TeamMetrics, ATieKeepsTheLowerAgentsCopy) {
  const std::vector<Vec2> person{Vec2(0, 0)};
  std::vector<agents::AgentBelief> beliefs(3);
  beliefs[0].tracks = {track({4, 2}, Vec2(900, 0), 1.0), track({-1, 0}, Vec2(3, 0), 1.0)};
  beliefs[1].tracks = {track({-1, 0}, Vec2(0, 4), 1.0), track({4, 2}, Vec2(950, 0), 0.5)};
  beliefs[2].tracks = {track({-1, 0}, Vec2(0, 2), 1.0)};
  TeamMetrics metrics;
  // Key {-1,0}: (3, 0) kept against the equal traces of (0, 4) and (0, 2): OSPA over two
  // estimates (the other key at 900 or 950 m is false) = sqrt((9 + 2500) / 2).
  TeamFigures f = metrics.compute(person, beliefs);
  EXPECT_EQ(f.estimates, 2);
  EXPECT_NEAR(f.ospa, std::sqrt((9.0 + 2500.0) / 2.0), 1e-12);
  beliefs[2].tracks[0].belief.P *= 0.5;  // now strictly less: agent 2's (0, 2) wins, d² = 4
  f = metrics.compute(person, beliefs);
  EXPECT_NEAR(f.ospa, std::sqrt((4.0 + 2500.0) / 2.0), 1e-12);
}

}  // namespace
}  // namespace canopy::sim
