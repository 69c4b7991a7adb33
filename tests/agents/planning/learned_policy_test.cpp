// The learned planner's observation and network (issue 54) against numbers worked by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "agents/planning/observation.h"
#include "agents/planning/policy_network.h"

namespace canopy::agents::planning {
namespace {

// A network of one layer per part: φ_T = ReLU(track dx), φ_M = ReLU(mate dy + 0.1); the head
// reads self[0], mean φ_T, max φ_T, mean φ_M, max φ_M with the weights below.
PolicyNetwork tinyNetwork() {
  PolicyNetwork net;
  DenseLayer t{Eigen::MatrixXd::Zero(1, kTrackFeatures), Eigen::VectorXd::Zero(1)};
  t.weight(0, 0) = 1.0;
  DenseLayer m{Eigen::MatrixXd::Zero(1, kMateFeatures), Eigen::VectorXd::Constant(1, 0.1)};
  m.weight(0, 1) = 1.0;
  DenseLayer h{Eigen::MatrixXd::Zero(2, kSelfFeatures + 4), Eigen::VectorXd::Zero(2)};
  h.weight(0, 0) = 1.0;                   // self[0]
  h.weight(0, kSelfFeatures) = 2.0;       // mean φ_T
  h.weight(0, kSelfFeatures + 1) = -1.0;  // max φ_T
  h.weight(0, kSelfFeatures + 2) = 0.5;   // mean φ_M
  h.weight(1, kSelfFeatures + 3) = 1.0;   // max φ_M
  h.bias(1) = -0.2;
  net.track = {t};
  net.mate = {m};
  net.head = {h};
  return net;
}

Observation tinyObservation() {
  Observation o;
  o.self.assign(kSelfFeatures, 0.0);
  o.self[0] = 1.0;
  o.tracks.assign(2 * kTrackFeatures, 0.0);
  o.tracks[0] = 0.5;
  o.tracks[kTrackFeatures] = -0.2;
  o.mates.assign(kMateFeatures, 0.0);
  o.mates[1] = 0.3;
  return o;
}

TEST(PolicyNetwork, EqualsTheHandComputedOutput) {
  const PolicyNetwork net = tinyNetwork();
  ASSERT_EQ(net.shapeError(), "");
  // φ_T: ReLU(0.5) = 0.5, ReLU(−0.2) = 0 → mean 0.25, max 0.5. φ_M: ReLU(0.3 + 0.1) = 0.4.
  // ρ_0 = 1 + 2·0.25 − 0.5 + 0.5·0.4 = 1.2; ρ_1 = 0.4 − 0.2 = 0.2.
  const Vec2 u = net.output(tinyObservation());
  EXPECT_NEAR(u.x(), std::tanh(1.2), 1e-15);
  EXPECT_NEAR(u.y(), std::tanh(0.2), 1e-15);
  // v_max·u = (4.168, 0.987) m/s, shorter than v_max: kept.
  const Vec2 a = net.command(tinyObservation(), 5.0);
  EXPECT_NEAR(a.x(), 5.0 * 0.83365460701215521, 1e-12);
  EXPECT_NEAR(a.y(), 5.0 * 0.19737532022490401, 1e-12);
}

TEST(PolicyNetwork, EmptySetsPoolToZeroAndLongCommandsAreCut) {
  const PolicyNetwork net = tinyNetwork();
  Observation o = tinyObservation();
  o.tracks.clear();
  o.mates.clear();
  o.self[0] = 30.0;  // ρ = (30, −0.2)
  const Vec2 u = net.output(o);
  EXPECT_NEAR(u.x(), std::tanh(30.0), 1e-15);
  EXPECT_NEAR(u.y(), std::tanh(-0.2), 1e-15);
  o.self[0] = 1.0;
  PolicyNetwork both = net;
  both.head[0].bias(1) = 30.0;  // ρ = (1, 30): u ≈ (0.762, 1), |v_max·u| > v_max
  const Vec2 a = both.command(o, 5.0);
  EXPECT_NEAR(a.norm(), 5.0, 1e-12);
  EXPECT_NEAR(a.y() / a.x(), 1.0 / std::tanh(1.0), 1e-12);
}

TEST(PolicyNetwork, OrderOfTracksAndTeammatesDoesNotMatter) {
  PolicyNetwork net;
  // Two layers per part with fixed pseudo-random weights.
  auto layer = [](int out, int in, double s) {
    DenseLayer l{Eigen::MatrixXd(out, in), Eigen::VectorXd(out)};
    for (int i = 0; i < out; ++i) {
      for (int j = 0; j < in; ++j) l.weight(i, j) = std::sin(s + 1.7 * i + 0.31 * j);
      l.bias(i) = 0.1 * std::cos(s + i);
    }
    return l;
  };
  net.track = {layer(6, kTrackFeatures, 1), layer(5, 6, 2)};
  net.mate = {layer(4, kMateFeatures, 3), layer(3, 4, 4)};
  net.head = {layer(7, kSelfFeatures + 16, 5), layer(2, 7, 6)};
  ASSERT_EQ(net.shapeError(), "");
  Observation o;
  for (int i = 0; i < kSelfFeatures; ++i) o.self.push_back(0.1 * i - 1);
  for (int i = 0; i < 3 * kTrackFeatures; ++i) o.tracks.push_back(std::cos(0.7 * i));
  for (int i = 0; i < 2 * kMateFeatures; ++i) o.mates.push_back(std::sin(0.9 * i));
  Observation swapped = o;
  std::rotate(swapped.tracks.begin(), swapped.tracks.begin() + kTrackFeatures, swapped.tracks.end());
  std::rotate(swapped.mates.begin(), swapped.mates.begin() + kMateFeatures, swapped.mates.end());
  const Vec2 a = net.output(o), b = net.output(swapped);
  EXPECT_NEAR(a.x(), b.x(), 1e-15);
  EXPECT_NEAR(a.y(), b.y(), 1e-15);
}

TEST(PolicyNetwork, ShapeErrorsNameTheLayer) {
  PolicyNetwork net = tinyNetwork();
  net.head[0].weight.conservativeResize(2, kSelfFeatures + 3);
  EXPECT_EQ(net.shapeError().rfind("layers.head[0].weight: expected rows of 35 numbers", 0), 0u)
      << net.shapeError();
  net = tinyNetwork();
  net.track[0].bias.resize(2);
  EXPECT_EQ(net.shapeError().rfind("layers.track[0].bias: expected 1 numbers", 0), 0u)
      << net.shapeError();
}

TEST(Observation, FeaturesWorkedByHand) {
  UavState me, mate;
  me.position = Vec2(10, 0);
  mate.position = Vec2(30, 0);
  me.footprint.size = mate.footprint.size = Vec2(20, 20);  // circumradius √200 m
  const std::vector<UavState> uavs = {me, mate};
  TargetGaussian t;
  t.x << 10, 20, 0, 1;
  t.P = Eigen::Matrix4d::Identity();
  t.P(0, 0) = 4;
  t.P(1, 1) = 9;
  t.P(0, 1) = t.P(1, 0) = 3;  // ρ = 3/(2·3) = 0.5
  const std::vector<TargetGaussian> tracks = {t};
  // Its own previous plan flies (0, −2) m/s; the teammate intends (1, 0) m/s for H = 5 s.
  const std::vector<Plan> intentions = {Plan{{Vec2(0, -2)}, 0.0}, Plan{{Vec2(1, 0)}, 0.0}};
  world::TreeDef tree;
  tree.centre = Vec2(10, 0);
  tree.radius = 3.0;
  const OcclusionMap map({tree});
  const Observation o = observe(0, uavs, tracks, &map, intentions, 5, 1.0);
  ASSERT_EQ(o.self.size(), static_cast<std::size_t>(kSelfFeatures));
  const double r = std::sqrt(200.0) / 20.0;
  EXPECT_DOUBLE_EQ(o.self[0], 1.0);  // 5 m/s / 5
  EXPECT_DOUBLE_EQ(o.self[1], r);
  EXPECT_DOUBLE_EQ(o.self[2], 0.1);
  EXPECT_DOUBLE_EQ(o.self[3], 0.1);
  EXPECT_DOUBLE_EQ(o.self[4], 0.0);
  EXPECT_DOUBLE_EQ(o.self[5], -0.4);
  // The centre cell's samples (±2, ±2) m lie 2.83 m from the crown's centre (radius 3): all
  // hidden; every other cell's nearest sample is 6.3 m away.
  for (int c = 0; c < kOcclusionCells * kOcclusionCells; ++c)
    EXPECT_DOUBLE_EQ(o.self[6 + c], c == 12 ? 1.0 : 0.0) << c;
  const std::vector<double> track = {0.0, 1.0, 0.0, 0.2, 0.1, 0.15, 0.5, std::log(14.0) / 5.0,
                                     // ahead (10, 25) − the mate's end (35, 0), over 20 m
                                     -1.25, 1.25, 1.0};
  ASSERT_EQ(o.tracks.size(), track.size());
  for (std::size_t k = 0; k < track.size(); ++k) EXPECT_NEAR(o.tracks[k], track[k], 1e-15) << k;
  const std::vector<double> mate_row = {1.0, 0.0, 0.2, 0.0, 0.25, 0.0, r};
  ASSERT_EQ(o.mates.size(), mate_row.size());
  for (std::size_t k = 0; k < mate_row.size(); ++k) EXPECT_NEAR(o.mates[k], mate_row[k], 1e-15) << k;
}

}  // namespace
}  // namespace canopy::agents::planning
