#pragma once
// Gaussian beliefs: targets (px, py, vx, vy) and trees (cx, cy, r).
#include "core/types.h"

namespace canopy::agents {

template <int N>
struct Gaussian {
  Eigen::Matrix<double, N, 1> x = Eigen::Matrix<double, N, 1>::Zero();      // mean
  Eigen::Matrix<double, N, N> P = Eigen::Matrix<double, N, N>::Identity();  // covariance
};

using TargetGaussian = Gaussian<4>;  // ξ = (px, py, vx, vy): m, m, m/s, m/s
using TreeGaussian = Gaussian<3>;    // (cx, cy, r): m

}  // namespace canopy::agents
