#include "agents/tracking/visibility.h"

#include <Eigen/Cholesky>
#include <cmath>

namespace canopy::agents::tracking {

bool targetVisible(const Vec2& p, const sensing::Footprint& footprint, const OcclusionMap& map,
                   const CameraOcclusion& camera, const Vec2& sensor, double sensor_height) {
  if (!footprint.contains(p)) return false;
  if (camera.targets == sensing::OcclusionModel::line_of_sight)
    return !map.blocksSegment(sensor, p);
  if (camera.targets == sensing::OcclusionModel::volumes)  // (sensor, h) → (p, head) in 3-D
    return !map.blocksSight(sensor, sensor_height, p, sensing::kTargetHeight);
  return !map.occludes(p);
}

double visibleProbability(const Vec2& mean, const Mat2& P_pos, const sensing::Footprint& footprint,
                          const OcclusionMap& map, const CameraOcclusion& camera,
                          const Vec2& sensor, double sensor_height) {
  constexpr double kCentreWeight = 1.0 / 3.0;  // κ / (n + κ), n = 2, κ = 1
  constexpr double kSideWeight = 1.0 / 6.0;    // 1 / (2 (n + κ))
  const auto visible = [&](const Vec2& p) {
    return targetVisible(p, footprint, map, camera, sensor, sensor_height);
  };
  const double centre = visible(mean) ? 1.0 : 0.0;
  const Eigen::LLT<Mat2> llt(P_pos);
  if (llt.info() != Eigen::Success || !P_pos.allFinite()) return centre;
  const Mat2 spread = std::sqrt(3.0) * Mat2(llt.matrixL());  // √(n + κ) L
  double p = kCentreWeight * centre;                         // P(visible) = Σ wᵢ 1[sᵢ visible]
  for (int i = 0; i < 2; ++i) {
    const Vec2 offset = spread.col(i);
    if (visible(mean + offset)) p += kSideWeight;
    if (visible(mean - offset)) p += kSideWeight;
  }
  return p;
}

}  // namespace canopy::agents::tracking
