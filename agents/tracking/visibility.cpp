#include "agents/tracking/visibility.h"

#include <Eigen/Cholesky>
#include <cmath>

namespace canopy::agents::tracking {

bool targetVisible(const Vec2& p, const sensing::Footprint& footprint, const OcclusionMap& map,
                   const CameraOcclusion& camera, const Vec2& sensor) {
  if (!footprint.contains(p)) return false;
  if (camera.targets == sensing::OcclusionModel::line_of_sight)
    return !map.blocksSegment(sensor, p);
  return !map.occludes(p);
}

double visibleProbability(const Vec2& mean, const Mat2& P_pos, const sensing::Footprint& footprint,
                          const OcclusionMap& map, const CameraOcclusion& camera,
                          const Vec2& sensor) {
  constexpr double kCentreWeight = 1.0 / 3.0;  // κ / (n + κ), n = 2, κ = 1
  constexpr double kSideWeight = 1.0 / 6.0;    // 1 / (2 (n + κ))
  const double centre = targetVisible(mean, footprint, map, camera, sensor) ? 1.0 : 0.0;
  const Eigen::LLT<Mat2> llt(P_pos);
  if (llt.info() != Eigen::Success || !P_pos.allFinite()) return centre;
  const Mat2 spread = std::sqrt(3.0) * Mat2(llt.matrixL());  // √(n + κ) L
  double p = kCentreWeight * centre;                         // P(visible) = Σ wᵢ 1[sᵢ visible]
  for (int i = 0; i < 2; ++i) {
    const Vec2 offset = spread.col(i);
    if (targetVisible(mean + offset, footprint, map, camera, sensor)) p += kSideWeight;
    if (targetVisible(mean - offset, footprint, map, camera, sensor)) p += kSideWeight;
  }
  return p;
}

}  // namespace canopy::agents::tracking
