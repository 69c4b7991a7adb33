#pragma once
// Small builders shared by the fusion tests: tracks, random SPD matrices, and a team whose
// lists live in the test.
#include <Eigen/Core>
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

/// The lists of a team of UAVs, owned by the test.
struct Team {
  explicit Team(int agents)
      : targets(static_cast<std::size_t>(agents)),
        trees(static_cast<std::size_t>(agents)),
        positions(static_cast<std::size_t>(agents), Vec2::Zero()) {}

  void fuse(TeamFusion& fusion) {
    std::vector<AgentTracks> view;
    for (std::size_t i = 0; i < targets.size(); ++i) {
      view.push_back({&targets[i], &trees[i], positions[i]});
    }
    fusion.fuse(view);
  }

  std::vector<std::vector<tracking::TargetTrack>> targets;
  std::vector<std::vector<tracking::TreeTrack>> trees;
  std::vector<Vec2> positions;  // m
};

}  // namespace canopy::agents::fusion::test
