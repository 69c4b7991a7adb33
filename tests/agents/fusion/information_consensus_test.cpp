// Consensus through the public entry point, against averages and filters computed here by a
// second method (explicit LU inverses, covariance-form Kalman updates).
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "agents/fusion/team_fusion.h"
#include "fusion_test_support.h"

namespace canopy::agents::fusion {
namespace {

using test::Team;

constexpr double kInf = std::numeric_limits<double>::infinity();

struct InfoPair {
  Mat4 omega = Mat4::Zero();
  Vec4 q = Vec4::Zero();
};

InfoPair information(const TargetGaussian& g) {
  const Mat4 omega = g.P.inverse();  // LU, not the Cholesky solve of the code under test
  return {omega, omega * g.x};
}

InfoPair mean(const std::vector<InfoPair>& pairs) {
  InfoPair m;
  for (const InfoPair& p : pairs) {
    m.omega += p.omega / static_cast<double>(pairs.size());
    m.q += p.q / static_cast<double>(pairs.size());
  }
  return m;
}

/// Largest relative distance of any agent's information pair from `target`.
double spread(const Team& team, const InfoPair& target) {
  double worst = 0.0;
  for (const auto& list : team.targets) {
    const InfoPair p = information(list.at(0).posterior);
    const double d = (p.omega - target.omega).norm() / target.omega.norm() +
                     (p.q - target.q).norm() / target.q.norm();
    worst = std::max(worst, d);
  }
  return worst;
}

/// N agents, each with one track of the same key near (20, 30), random covariance.
Team randomTeam(int agents, std::uint64_t seed) {
  RandomStream rng(seed, "test.consensus");
  Team team(agents);
  for (int i = 0; i < agents; ++i) {
    const Vec4 x = Vec4(20.0, 30.0, 1.0, -1.0) + test::randomVector<4>(rng, 0.5);
    team.targets[i] = {test::makeTrack<4>({-1, 0}, x, test::randomSpd<4>(rng, 0.5))};
  }
  return team;
}

std::vector<InfoPair> informationOf(const Team& team) {
  std::vector<InfoPair> pairs;
  for (const auto& list : team.targets) pairs.push_back(information(list.at(0).posterior));
  return pairs;
}

/// Kalman update in covariance (Joseph) form with H = [I₂ 0] (Bar-Shalom et al. 2001, §5.2).
TargetGaussian kalmanUpdate(const TargetGaussian& prior, const Vec2& z, const Mat2& R) {
  Mat24 H = Mat24::Zero();
  H(0, 0) = H(1, 1) = 1.0;
  const Mat2 S = H * prior.P * H.transpose() + R;
  const Mat42 K = prior.P * H.transpose() * S.inverse();
  const Mat4 I_KH = Mat4::Identity() - K * H;
  return {prior.x + K * (z - H * prior.x),
          I_KH * prior.P * I_KH.transpose() + K * R * K.transpose()};
}

void expectGaussianNear(const TargetGaussian& actual, const TargetGaussian& expected, double tol) {
  EXPECT_LT((actual.x - expected.x).cwiseAbs().maxCoeff(), tol) << actual.x.transpose();
  EXPECT_LT((actual.P - expected.P).cwiseAbs().maxCoeff(), tol) << actual.P;
}

TEST(Ci, OneRoundOnACompleteGraphIsExactlyTheAverage) {
  Team team = randomTeam(5, 1);
  const InfoPair average = mean(informationOf(team));
  FusionConfig config;
  config.rounds = 1;
  TeamFusion fusion(config, 5, 1);
  team.fuse(fusion);
  const TargetGaussian expected{average.omega.inverse() * average.q, average.omega.inverse()};
  for (const auto& list : team.targets) expectGaussianNear(list[0].posterior, expected, 1e-9);
}

TEST(Ci, ConvergesToTheNetworkAverageAsRoundsGrow) {
  // A path 0 — 1 — 2 — 3 — 4: the slowest graph on five agents.
  const Team initial = randomTeam(5, 2);
  const InfoPair average = mean(informationOf(initial));
  double previous = kInf;
  for (const int rounds : {1, 3, 10, 30, 300}) {
    Team team = initial;
    team.positions = {{0, 0}, {10, 0}, {20, 0}, {30, 0}, {40, 0}};
    FusionConfig config;
    config.rounds = rounds;
    config.comm_range = 15.0;
    TeamFusion fusion(config, 5, 1);
    team.fuse(fusion);
    const double error = spread(team, average);
    EXPECT_LT(error, previous) << rounds << " rounds";
    previous = error;
    // Symmetric, doubly stochastic weights keep the team's mean at every round.
    const InfoPair kept = mean(informationOf(team));
    EXPECT_LT((kept.omega - average.omega).norm() / average.omega.norm(), 1e-9);
    EXPECT_LT((kept.q - average.q).norm() / average.q.norm(), 1e-9);
  }
  EXPECT_LT(previous, 1e-9);
}

TEST(Ci, LostMessagesKeepEveryUpdateAConvexCombination) {
  // Ω_i = s_i I: any convex combination is c I with c between the smallest and largest s_i.
  const int n = 6;
  Team team(n);
  for (int i = 0; i < n; ++i) {
    const double s = 1.0 + i;  // 1/m² .. 6/m²
    team.targets[i] = {test::targetAt({-1, 0}, 0.1 * i, 0.0, 1.0 / s)};
  }
  FusionConfig config;
  config.comm_drop = 0.5;
  TeamFusion fusion(config, n, 7);
  for (int step = 0; step < 4; ++step) team.fuse(fusion);
  EXPECT_GT(fusion.diagnostics().lost_messages, 0);
  for (const auto& list : team.targets) {
    const Mat4 omega = list[0].posterior.P.inverse();
    const double c = omega(0, 0);
    EXPECT_GE(c, 1.0 - 1e-12);
    EXPECT_LE(c, 6.0 + 1e-12);
    EXPECT_LT((omega - c * Mat4::Identity()).norm(), 1e-9);
  }
}

TEST(Ci, TeamConvergesOnceLostMessagesResume) {
  // A ring of six (each UAV hears its two neighbours), half the messages lost for three steps,
  // then none: the agents agree again.
  const int n = 6;
  Team team = randomTeam(n, 3);
  for (int i = 0; i < n; ++i) {
    const double angle = 2.0 * std::numbers::pi * i / n;
    team.positions[i] = 100.0 * Vec2(std::cos(angle), std::sin(angle));  // neighbours 100 m apart
  }
  FusionConfig lossy;
  lossy.comm_range = 120.0;
  lossy.comm_drop = 0.5;
  TeamFusion lossy_fusion(lossy, n, 11);
  for (int step = 0; step < 3; ++step) team.fuse(lossy_fusion);
  EXPECT_GT(lossy_fusion.diagnostics().lost_messages, 0);

  FusionConfig clean = lossy;
  clean.comm_drop = 0.0;
  TeamFusion clean_fusion(clean, n, 11);
  for (int step = 0; step < 40; ++step) team.fuse(clean_fusion);
  EXPECT_LT(spread(team, information(team.targets[0][0].posterior)), 1e-9);
}

TEST(Ci, FusionIsReproducibleForASeed) {
  FusionConfig config;
  config.comm_drop = 0.4;
  config.comm_range = 15.0;
  auto run = [&](std::uint64_t seed) {
    Team team = randomTeam(5, 4);
    team.positions = {{0, 0}, {10, 0}, {20, 0}, {30, 0}, {40, 0}};
    TeamFusion fusion(config, 5, seed);
    for (int step = 0; step < 5; ++step) team.fuse(fusion);
    return team;
  };
  const Team a = run(21), b = run(21), c = run(22);
  bool differs = false;
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(a.targets[i][0].posterior.x, b.targets[i][0].posterior.x);
    EXPECT_EQ(a.targets[i][0].posterior.P, b.targets[i][0].posterior.P);
    differs = differs || a.targets[i][0].posterior.x != c.targets[i][0].posterior.x;
  }
  EXPECT_TRUE(differs) << "another seed loses other messages";
}

/// A shared prior, each agent's own measurement; returns the centralised filter's posterior.
TargetGaussian measureTeam(Team& team, int measuring, RandomStream& rng) {
  TargetGaussian prior;
  prior.x << 5.0, -3.0, 0.7, 0.2;
  prior.P = test::randomSpd<4>(rng, 1.0);
  TargetGaussian central = prior;
  for (int i = 0; i < measuring; ++i) {
    const Vec2 z = prior.x.head<2>() + test::randomVector<2>(rng, 0.3);
    const Mat2 R = test::randomSpd<2>(rng, 0.2);
    tracking::TargetTrack track = test::makeTrack<4>({-1, 0}, prior.x, prior.P);
    track.posterior = kalmanUpdate(prior, z, R);
    track.detected = true;
    team.targets[i] = {track};
    central = kalmanUpdate(central, z, R);  // the centralised filter: every measurement in turn
  }
  return central;
}

TEST(Hcmci, EqualsTheCentralisedKalmanFilterOnACompleteGraph) {
  RandomStream rng(5, "test.hcmci");
  Team team(4);
  const TargetGaussian central = measureTeam(team, 4, rng);
  FusionConfig config;
  config.method = FusionMethod::hcmci;
  TeamFusion fusion(config, 4, 1);
  team.fuse(fusion);
  for (const auto& list : team.targets) expectGaussianNear(list[0].posterior, central, 1e-9);
}

TEST(Hcmci, AnAdoptedCopyBringsNoMeasurement) {
  // Agent 3 has no track: it adopts one and must not count a measurement twice.
  RandomStream rng(6, "test.hcmci");
  Team team(4);
  const TargetGaussian central = measureTeam(team, 3, rng);
  FusionConfig config;
  config.method = FusionMethod::hcmci;
  TeamFusion fusion(config, 4, 1);
  team.fuse(fusion);
  for (const auto& list : team.targets) {
    ASSERT_EQ(list.size(), 1u);
    expectGaussianNear(list[0].posterior, central, 1e-9);
  }
}

TEST(ObserverAverage, AveragesOnlyTheObserversAndOthersAdoptIt) {
  Team team = randomTeam(3, 8);
  team.targets[0][0].detected = true;
  team.targets[1][0].detected = true;
  const std::vector<InfoPair> pairs = informationOf(team);
  const InfoPair average = mean({pairs[0], pairs[1]});
  FusionConfig config;
  config.method = FusionMethod::observer_average;
  TeamFusion fusion(config, 3, 1);
  team.fuse(fusion);
  const TargetGaussian expected{average.omega.inverse() * average.q, average.omega.inverse()};
  for (const auto& list : team.targets) expectGaussianNear(list[0].posterior, expected, 1e-9);
}

TEST(ObserverAverage, EachKeepsItsOwnWhenNobodyObserved) {
  Team team = randomTeam(3, 9);
  const Team before = team;
  FusionConfig config;
  config.method = FusionMethod::observer_average;
  TeamFusion fusion(config, 3, 1);
  team.fuse(fusion);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(team.targets[i][0].posterior.x, before.targets[i][0].posterior.x);
    EXPECT_EQ(team.targets[i][0].posterior.P, before.targets[i][0].posterior.P);
  }
}

}  // namespace
}  // namespace canopy::agents::fusion

namespace canopy::agents::fusion {
namespace {

// CI's L rounds on a complete graph of n agents of whom c hold the track, by the definition:
// y_i ← Σ_{j holder, j ≠ i} (1/n) y_j + (1 − (c − 1)/n) y_i (the weight of each agent without the
// track stays with the receiver), applied to the information pairs and the log-odds.
void roundsByDefinition(std::vector<InfoPair>& info, std::vector<double>& log_odds, int n,
                        int rounds) {
  const int c = static_cast<int>(info.size());
  const double pi = 1.0 / n;
  for (int round = 0; round < rounds; ++round) {
    std::vector<InfoPair> next(info.size());
    std::vector<double> next_odds(info.size(), 0.0);
    for (int i = 0; i < c; ++i) {
      next[i].omega = (1.0 - (c - 1) * pi) * info[i].omega;
      next[i].q = (1.0 - (c - 1) * pi) * info[i].q;
      next_odds[i] = (1.0 - (c - 1) * pi) * log_odds[i];
      for (int j = 0; j < c; ++j) {
        if (j == i) continue;
        next[i].omega += pi * info[j].omega;
        next[i].q += pi * info[j].q;
        next_odds[i] += pi * log_odds[j];
      }
    }
    info = next;
    log_odds = next_odds;
  }
}

TEST(Ci, ManyHoldersOnACompleteGraphMixAsTheRoundsDo) {
  // 18 of 20 agents hold the track (the closed form from 16 members on), 5 of 20 (the rounds):
  // both against the definition, three rounds, β = 1 − c/n ≠ 0.
  for (const int holders : {18, 5}) {
    const int n = 20, rounds = 3;
    RandomStream rng(7, "test.consensus.closed_form");
    std::vector<std::vector<tracking::TargetTrack>> lists(n);
    Clusters clusters;
    clusters.start = {0};
    std::vector<InfoPair> expected;
    std::vector<double> odds;
    for (int i = 0; i < holders; ++i) {
      const Vec4 x = Vec4(20.0, 30.0, 1.0, -1.0) + test::randomVector<4>(rng, 0.5);
      lists[i] = {test::makeTrack<4>({-1, 0}, x, test::randomSpd<4>(rng, 0.5))};
      lists[i][0].existence = 0.2 + 0.7 * rng.uniform();
      expected.push_back(information(lists[i][0].posterior));
      odds.push_back(std::log(lists[i][0].existence / (1.0 - lists[i][0].existence)));
      clusters.members.push_back({i, 0, false});
    }
    clusters.start.push_back(holders);
    clusters.keys = {{-1, 0}};
    CommGraph graph;
    graph.build(std::vector<Vec2>(n, Vec2::Zero()), kInf);
    ASSERT_TRUE(graph.complete());
    FusionConfig config;
    config.rounds = rounds;
    FusionDiagnostics diagnostics;
    InformationConsensus<4>().run(lists, clusters, graph, config, diagnostics);
    roundsByDefinition(expected, odds, n, rounds);
    for (int i = 0; i < holders; ++i) {
      const InfoPair got = information(lists[i][0].posterior);
      EXPECT_LT((got.omega - expected[i].omega).norm() / expected[i].omega.norm(), 1e-10)
          << holders << " holders, agent " << i;
      EXPECT_LT((got.q - expected[i].q).norm() / expected[i].q.norm(), 1e-10) << i;
      EXPECT_NEAR(std::log(lists[i][0].existence / (1.0 - lists[i][0].existence)), odds[i], 1e-10)
          << i;
    }
    EXPECT_EQ(diagnostics.numerical_failures, 0);
  }
}


TEST(Ci, CopiesWithTheSameBitsFuseAsEachOnItsOwn) {
  // 14 agents hold the track: 8 copies with the same bits, 4 others, 2 with a NaN covariance.
  // Fused once as they are (the copies converted once) and once with each copy's zero velocity
  // written as −0.0 in all but the first (equal values, other bits: each converted on its own),
  // every posterior has the same values and the failures are counted alike.
  const int n = 14;
  auto fuse = [&](bool distinct_bits, FusionDiagnostics& diagnostics) {
    RandomStream rng(9, "test.consensus.same_bits");
    std::vector<std::vector<tracking::TargetTrack>> lists(n);
    const Mat4 shared_P = test::randomSpd<4>(rng, 0.5);
    Clusters clusters;
    clusters.start = {0, n};
    clusters.keys = {{-1, 0}};
    for (int i = 0; i < n; ++i) {
      Vec4 x(20.0, 30.0, 1.0, 0.0);
      Mat4 P = shared_P;
      if (i >= 8 && i < 12) {
        x += test::randomVector<4>(rng, 0.5);
        P = test::randomSpd<4>(rng, 0.5);
      }
      if (i >= 12) P(1, 1) = std::numeric_limits<double>::quiet_NaN();
      if (distinct_bits && i > 0 && i < 8) x(3) = -0.0;
      lists[i] = {test::makeTrack<4>({-1, 0}, x, P)};
      clusters.members.push_back({i, 0, false});
    }
    CommGraph graph;
    graph.build(std::vector<Vec2>(n, Vec2::Zero()), kInf);
    FusionConfig config;
    config.rounds = 3;
    InformationConsensus<4>().run(lists, clusters, graph, config, diagnostics);
    return lists;
  };
  FusionDiagnostics reused, alone;
  const auto a = fuse(false, reused);
  const auto b = fuse(true, alone);
  for (int i = 0; i < 12; ++i) {  // the two with NaN take no part and keep their posterior
    for (int r = 0; r < 4; ++r) {
      EXPECT_EQ(a[i][0].posterior.x(r), b[i][0].posterior.x(r)) << i;
      for (int c = 0; c < 4; ++c) EXPECT_EQ(a[i][0].posterior.P(r, c), b[i][0].posterior.P(r, c));
    }
  }
  EXPECT_NE(a[0][0].posterior.x, a[8][0].posterior.x);  // fused, not all one value
  EXPECT_EQ(reused.numerical_failures, 2);
  EXPECT_EQ(alone.numerical_failures, 2);
}

}  // namespace
}  // namespace canopy::agents::fusion
