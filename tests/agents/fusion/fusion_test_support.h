#pragma once
// Small builders shared by the fusion tests: tracks, random SPD matrices, a team whose lists live
// in the test, and a toy local tracker for closed loops.
#include <Eigen/Core>
#include <Eigen/LU>
#include <cmath>
#include <utility>
#include <vector>

#include "agents/fusion/team_fusion.h"
#include "core/random.h"

namespace canopy::agents::fusion::test {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

template <int N>
tracking::Track<N> makeTrack(TrackKey key, const Eigen::Matrix<double, N, 1>& x,
                             const Eigen::Matrix<double, N, N>& P, sensing::LabelId label = 1,
                             bool confirmed = true) {
  tracking::Track<N> track;
  track.key = key;
  track.label = label;
  track.prior = {x, P};
  track.posterior = {x, P};
  track.status = confirmed ? tracking::TrackStatus::confirmed : tracking::TrackStatus::tentative;
  return track;
}

inline tracking::TargetTrack targetAt(TrackKey key, double px, double py, double variance = 1.0,
                                      sensing::LabelId label = 1, bool confirmed = true) {
  return makeTrack<4>(key, Vec4(px, py, 0.0, 0.0), variance * Mat4::Identity(), label, confirmed);
}

/// A = B Bᵀ + floor·I with B uniform in [−1, 1]: symmetric positive definite.
template <int N>
Eigen::Matrix<double, N, N> randomSpd(RandomStream& rng, double floor) {
  Eigen::Matrix<double, N, N> B;
  for (int r = 0; r < N; ++r) {
    for (int c = 0; c < N; ++c) B(r, c) = rng.uniform(-1.0, 1.0);
  }
  return B * B.transpose() + floor * Eigen::Matrix<double, N, N>::Identity();
}

template <int N>
Eigen::Matrix<double, N, 1> randomVector(RandomStream& rng, double half_width) {
  Eigen::Matrix<double, N, 1> v;
  for (int r = 0; r < N; ++r) v(r) = rng.uniform(-half_width, half_width);
  return v;
}

/// The toy tracker's step (s), detection range (m, a disc around the UAV) and measurement
/// variance (m², per axis).
constexpr double kToyDt = 0.2;
constexpr double kToyFootprint = 35.0;
constexpr double kToyMeasurementVar = 0.5;

/// A toy scene on a strip `length` m long, y in [10, 50] m: walkers at constant velocities
/// (|v_x| ≤ 2, |v_y| ≤ 0.5 m/s), then static trees, drawn in that order from `layout`.
struct ToyScene {
  std::vector<Vec2> targets, velocities, trees;
  /// The walkers one toy step (kToyDt) on.
  void advance() {
    for (std::size_t t = 0; t < targets.size(); ++t) targets[t] += kToyDt * velocities[t];
  }
};

inline ToyScene toyScene(RandomStream& layout, int targets, int trees, double length) {
  ToyScene scene;
  for (int t = 0; t < targets; ++t) {
    scene.targets.emplace_back(layout.uniform(0.0, length), layout.uniform(10.0, 50.0));
    scene.velocities.emplace_back(layout.uniform(-2.0, 2.0), layout.uniform(-0.5, 0.5));
  }
  for (int k = 0; k < trees; ++k)
    scene.trees.emplace_back(layout.uniform(0.0, length), layout.uniform(10.0, 50.0));
  return scene;
}

/// Targets: NCV prediction over kToyDt (paper eq. 4), σ_a = 1 m/s². Trees: static.
template <int N>
Gaussian<N> toyPredict(const Gaussian<N>& g) {
  if constexpr (N == 3) {
    return g;
  } else {
    Mat4 F = Mat4::Identity();
    F(0, 2) = F(1, 3) = kToyDt;
    Mat4 Q = Mat4::Zero();
    const double q4 = std::pow(kToyDt, 4) / 4, q3 = std::pow(kToyDt, 3) / 2, q2 = kToyDt * kToyDt;
    for (int a = 0; a < 2; ++a) {
      Q(a, a) = q4;
      Q(a, a + 2) = Q(a + 2, a) = q3;
      Q(a + 2, a + 2) = q2;
    }
    return {F * g.x, F * g.P * F.transpose() + Q};
  }
}

/// Kalman update on the position (the first two states), covariance form.
template <int N>
Gaussian<N> toyUpdate(const Gaussian<N>& g, const Vec2& z) {
  const Mat2 S = g.P.template topLeftCorner<2, 2>() + kToyMeasurementVar * Mat2::Identity();
  const Eigen::Matrix<double, N, 2> K = g.P.template leftCols<2>() * S.inverse();
  Gaussian<N> out{g.x + K * (z - g.x.template head<2>()), g.P - K * S * K.transpose()};
  out.P = 0.5 * (out.P + out.P.transpose());
  return out;
}

/// One agent's toy tracking step: predict all, update the nearest gated track per detection of
/// a truth within kToyFootprint of the UAV, birth a tentative track otherwise (trees with a
/// 2 m radius), confirm on the second hit.
template <int N>
void trackLocally(std::vector<tracking::Track<N>>& tracks, const Vec2& uav,
                  const std::vector<Vec2>& truths, RandomStream& rng, int agent, int& serial) {
  for (auto& track : tracks) {
    track.prior = toyPredict(track.posterior);
    track.posterior = track.prior;
    track.detected = false;
  }
  for (const Vec2& truth : truths) {
    if ((truth - uav).norm() > kToyFootprint) continue;
    const Vec2 z = truth + std::sqrt(kToyMeasurementVar) * Vec2(rng.normal(), rng.normal());
    tracking::Track<N>* best = nullptr;
    double best_d2 = 9.21;
    for (auto& track : tracks) {
      const Mat2 S =
          track.prior.P.template topLeftCorner<2, 2>() + kToyMeasurementVar * Mat2::Identity();
      const Vec2 nu = z - track.prior.x.template head<2>();
      const double d2 = nu.dot(S.inverse() * nu);
      if (d2 < best_d2) {
        best_d2 = d2;
        best = &track;
      }
    }
    if (best) {
      best->posterior = toyUpdate(best->posterior, z);
      best->detected = true;
      if (++best->hits >= 2) best->status = tracking::TrackStatus::confirmed;
    } else {
      Eigen::Matrix<double, N, N> P = Eigen::Matrix<double, N, N>::Identity();
      P.template topLeftCorner<2, 2>() *= kToyMeasurementVar;
      Eigen::Matrix<double, N, 1> x = Eigen::Matrix<double, N, 1>::Zero();
      x.template head<2>() = z;
      sensing::LabelId label = 1;
      if constexpr (N == 3) {
        x(2) = 2.0;
        label = sensing::kTreeLabel;
      }
      tracks.push_back(makeTrack<N>({agent, serial++}, x, P, label, /*confirmed=*/false));
      tracks.back().hits = 1;
      tracks.back().detected = true;
    }
  }
}

/// The lists of a team of UAVs, owned by the test.
struct Team {
  explicit Team(int agents)
      : targets(static_cast<std::size_t>(agents)),
        trees(static_cast<std::size_t>(agents)),
        positions(static_cast<std::size_t>(agents), Vec2::Zero()) {}

  /// One fusion step; the test's lists then become the fused ones.
  void fuse(TeamFusion& fusion) {
    std::vector<AgentTracks> inputs;
    for (std::size_t i = 0; i < targets.size(); ++i) {
      inputs.push_back({targets[i], trees[i], positions[i]});
    }
    FusedTracks fused;
    fusion.fuse(inputs, fused);
    targets = std::move(fused.targets);
    trees = std::move(fused.trees);
  }

  std::vector<std::vector<tracking::TargetTrack>> targets;
  std::vector<std::vector<tracking::TreeTrack>> trees;
  std::vector<Vec2> positions;  // m
};

}  // namespace canopy::agents::fusion::test
