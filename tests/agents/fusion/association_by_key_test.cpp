// The association taken by key against pair by pair (track_association.h, "Work"), and the gate
// bound it rests on (association_gate.h) against an eigen-solver.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <climits>
#include <cmath>
#include <limits>
#include <vector>

#include "agents/fusion/association_gate.h"
#include "agents/fusion/track_association.h"
#include "fusion_test_support.h"

namespace canopy::agents::fusion {
namespace {

using test::randomSpd;
using test::targetAt;
using TargetList = std::vector<tracking::TargetTrack>;

double leastEigenvalue(const Mat2& S) {
  const Mat2 symmetric = 0.5 * (S + S.transpose());
  return Eigen::SelfAdjointEigenSolver<Mat2>(symmetric).eigenvalues().minCoeff();
}

TEST(AssociationGate, FloorIsBelowTheLeastEigenvalue) {
  RandomStream rng(5, "test.floor");
  int used = 0;
  for (int k = 0; k < 20000; ++k) {
    const Mat2 S = randomSpd<2>(rng, rng.uniform(0.0, 0.3));
    const double floor = eigenFloor(S);
    if (floor == 0.0) continue;
    ++used;
    const double lambda = leastEigenvalue(S);
    EXPECT_LE(floor, lambda);
    EXPECT_GE(floor, lambda * (1.0 - 1e-5));  // shaded by 10⁻⁶, not more
  }
  EXPECT_GT(used, 10000);
}

TEST(AssociationGate, FloorRefusesWhatTheBoundCannotCover) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(eigenFloor(Mat2{{1.0, 2.0}, {2.0, 1.0}}), 0.0);            // indefinite
  EXPECT_EQ(eigenFloor(Mat2{{1.0, 0.0}, {0.0, nan}}), 0.0);            // not finite
  EXPECT_EQ(eigenFloor(Mat2{{1.0, 0.0}, {0.0, 1e-4}}), 0.0);           // κ = 10⁴
  EXPECT_EQ(eigenFloor(Mat2{{1.0, 0.1}, {0.0, 1.0}}), 0.0);            // asymmetric
  EXPECT_NEAR(eigenFloor(Mat2{{1.0, 0.0}, {0.0, 1e-3}}), 1e-3, 2e-9);  // κ = 1000: used
  // [[2, 1], [1, 2]]: eigenvalues 1 and 3.
  EXPECT_NEAR(eigenFloor(Mat2{{2.0, 1.0}, {1.0, 2.0}}), 1.0, 2e-6);
}

TEST(AssociationGate, CoreCopiesPassHalfTheGate) {
  // Random copies in the core of a random centre: every pair's d², computed, is ≤ gate / 2.
  RandomStream rng(7, "test.core");
  const double gate = 9.21;
  int pairs = 0;
  for (int k = 0; k < 20000; ++k) {
    const Vec2 centre(rng.uniform(-1e4, 1e4), rng.uniform(-1e4, 1e4));
    Vec2 p[2];
    Mat2 S[2];
    bool core = true;
    for (int c = 0; c < 2; ++c) {
      S[c] = randomSpd<2>(rng, rng.uniform(0.001, 0.5));
      const double angle = rng.uniform(0.0, 6.283185307179586);
      const double reach = std::sqrt(0.25 * gate * eigenFloor(S[c])) * rng.uniform(0.0, 1.01);
      p[c] = centre + reach * Vec2(std::cos(angle), std::sin(angle));
      core = core && inGateCore((p[c] - centre).norm(), eigenFloor(S[c]), gate);
    }
    if (!core) continue;
    ++pairs;
    EXPECT_LE(mahalanobis2(p[0], S[0], p[1], S[1]), 0.5 * gate);
  }
  EXPECT_GT(pairs, 10000);
}

// A random team's lists: a pool of targets, each agent holding copies of some of them (most near
// the target, a few pulled away, some with another label), some tracks of its own, and now and
// then a key twice (which sends the association back to pair by pair).
struct RandomTeam {
  std::vector<Vec2> positions;
  std::vector<TargetList> lists;
  double range = std::numeric_limits<double>::infinity();
};

RandomTeam randomTeam(RandomStream& rng) {
  RandomTeam team;
  const int agents = 9 + static_cast<int>(rng.uniform(0.0, 40.0));
  const int targets = 1 + static_cast<int>(rng.uniform(0.0, 30.0));
  if (rng.bernoulli(0.5)) team.range = rng.uniform(20.0, 120.0);
  std::vector<Vec2> truth;
  std::vector<Mat2> shared;
  for (int t = 0; t < targets; ++t) {
    truth.emplace_back(rng.uniform(0.0, 100.0), rng.uniform(0.0, 100.0));
    shared.push_back(randomSpd<2>(rng, rng.uniform(0.01, 1.0)));
  }
  const bool duplicates = rng.bernoulli(0.1);
  for (int a = 0; a < agents; ++a) {
    team.positions.emplace_back(rng.uniform(0.0, 100.0), rng.uniform(0.0, 100.0));
    TargetList list;
    for (int t = 0; t < targets; ++t) {
      if (!rng.bernoulli(0.7)) continue;
      const TrackKey key{-1, t};
      const double spread = rng.bernoulli(0.8) ? 0.05 : rng.uniform(0.5, 6.0);
      tracking::TargetTrack track =
          targetAt(key, truth[t].x() + spread * rng.normal(), truth[t].y() + spread * rng.normal(),
                   1.0, rng.bernoulli(0.95) ? 1 : 2, rng.bernoulli(0.9));
      Mat2 S = rng.bernoulli(0.7) ? shared[t] : randomSpd<2>(rng, rng.uniform(0.0, 1.0));
      if (rng.bernoulli(0.02)) S(0, 1) += 0.5;  // asymmetric: outside the bound, gated exactly
      track.posterior.P.topLeftCorner<2, 2>() = S;
      list.push_back(track);
    }
    const int own = static_cast<int>(rng.uniform(0.0, 3.0));
    for (int k = 0; k < own; ++k) {
      list.push_back(targetAt({a, k}, rng.uniform(0.0, 100.0), rng.uniform(0.0, 100.0),
                              rng.uniform(0.2, 2.0), 1, rng.bernoulli(0.5)));
    }
    if (duplicates && a == 0 && !list.empty()) list.push_back(list.front());
    team.lists.push_back(list);
  }
  return team;
}

struct Outcome {
  std::vector<TargetList> lists;
  Clusters clusters;
  FusionDiagnostics diagnostics;
};

Outcome associate(const RandomTeam& team, int grouped_from, int steps, std::uint64_t seed) {
  Outcome outcome{team.lists, {}, {}};
  TrackAssociation<4> association(grouped_from);
  CommGraph graph;
  graph.build(team.positions, team.range);
  KeyMint mint(static_cast<int>(team.positions.size()));
  RandomStream drift(seed, "test.drift");  // the same drift for both ways
  for (int step = 0; step < steps; ++step) {
    association.associate(outcome.lists, graph, 9.21, mint, outcome.clusters, outcome.diagnostics);
    for (TargetList& list : outcome.lists) {
      for (tracking::TargetTrack& track : list) {
        track.posterior.x.head<2>() += 0.3 * Vec2(drift.normal(), drift.normal());
      }
    }
  }
  return outcome;
}

void expectSame(const Outcome& by_key, const Outcome& pairwise) {
  ASSERT_EQ(by_key.lists.size(), pairwise.lists.size());
  for (std::size_t a = 0; a < by_key.lists.size(); ++a) {
    ASSERT_EQ(by_key.lists[a].size(), pairwise.lists[a].size()) << "agent " << a;
    for (std::size_t k = 0; k < by_key.lists[a].size(); ++k) {
      EXPECT_EQ(by_key.lists[a][k].key, pairwise.lists[a][k].key) << "agent " << a;
      EXPECT_EQ(by_key.lists[a][k].posterior.x, pairwise.lists[a][k].posterior.x);
    }
  }
  EXPECT_EQ(by_key.clusters.start, pairwise.clusters.start);
  EXPECT_EQ(by_key.clusters.keys, pairwise.clusters.keys);
  ASSERT_EQ(by_key.clusters.members.size(), pairwise.clusters.members.size());
  for (std::size_t m = 0; m < by_key.clusters.members.size(); ++m) {
    EXPECT_EQ(by_key.clusters.members[m].agent, pairwise.clusters.members[m].agent);
    EXPECT_EQ(by_key.clusters.members[m].track, pairwise.clusters.members[m].track);
    EXPECT_EQ(by_key.clusters.members[m].adopted, pairwise.clusters.members[m].adopted);
  }
  const FusionDiagnostics& x = by_key.diagnostics;
  const FusionDiagnostics& y = pairwise.diagnostics;
  EXPECT_EQ(x.remembered_matches, y.remembered_matches);
  EXPECT_EQ(x.new_matches, y.new_matches);
  EXPECT_EQ(x.refused_matches, y.refused_matches);
  EXPECT_EQ(x.adoptions, y.adoptions);
  EXPECT_EQ(x.rekeys, y.rekeys);
}

TEST(AssociationByKey, SameAsPairByPairOnRandomTeams) {
  RandomStream rng(11, "test.teams");
  long remembered = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const RandomTeam team = randomTeam(rng);
    const Outcome by_key = associate(team, 0, 3, 100 + trial);
    const Outcome pairwise = associate(team, INT_MAX, 3, 100 + trial);
    SCOPED_TRACE(trial);
    expectSame(by_key, pairwise);
    remembered += by_key.diagnostics.remembered_matches;
  }
  EXPECT_GT(remembered, 10000);  // the memory was exercised, not only the assignment
}

TEST(AssociationByKey, ACopyBeyondTheGateIsNotRemembered) {
  // Ten agents, all in range, hold target {−1, 0}; agent 3's copy is 10 m off (d² = 50 > 9.21):
  // by hand, the 9 others give 36 remembered links and agent 3 none, so its copy is rekeyed.
  std::vector<TargetList> lists(10);
  for (int a = 0; a < 10; ++a) lists[a] = {targetAt({-1, 0}, a == 3 ? 60.0 : 50.0, 50.0)};
  CommGraph graph;
  graph.build(std::vector<Vec2>(10, Vec2::Zero()), std::numeric_limits<double>::infinity());
  TrackAssociation<4> association(0);
  KeyMint mint(10);
  Clusters clusters;
  FusionDiagnostics diagnostics;
  association.associate(lists, graph, 9.21, mint, clusters, diagnostics);
  EXPECT_EQ(diagnostics.remembered_matches, 36);
  EXPECT_EQ(diagnostics.new_matches, 0);
  EXPECT_EQ(diagnostics.rekeys, 1);
  EXPECT_EQ(clusters.size(), 2);
}

}  // namespace
}  // namespace canopy::agents::fusion
