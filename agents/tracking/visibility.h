#pragma once
// What a track expects of the own camera this scan: is its predicted position visible, and with
// what probability given its uncertainty (the P_D it expects is P_D × that probability).
#include "agents/occlusion_map.h"
#include "core/types.h"
#include "sensing/camera.h"
#include "sensing/footprint.h"
#include "sensing/visibility.h"

namespace canopy::agents::tracking {

/// What hides things from an agent's own camera (sensing/sensor.h's occlusionModel).
struct CameraOcclusion {
  sensing::OcclusionModel targets = sensing::OcclusionModel::canopy;
  bool ground_level = false;  // trees hide trees too
};

/// True when a target at p would be seen by the own camera at `sensor`: p inside the footprint
/// and not hidden by the own map — under a crown (from above), behind one on the segment from
/// the sensor (line of sight), or (`volumes`, issue 53) by a crown volume on the 3-D segment from
/// the camera, sensor_height (m) above `sensor`, to the walker's head at kTargetHeight, as
/// sensing tests it (sensing/visibility.h; a crown of the map without heights stands from the
/// ground up).
bool targetVisible(const Vec2& p, const sensing::Footprint& footprint, const OcclusionMap& map,
                   const CameraOcclusion& camera, const Vec2& sensor,
                   double sensor_height = sensing::kDefaultAltitude);

/// P(visible) of a target whose position is N(mean, P_pos), by the symmetric sigma points of the
/// unscented transform in 2-D with κ = 3 − n = 1 (Julier & Uhlmann 1997): the mean with weight
/// κ/(n + κ) = 1/3 and mean ± √(n + κ) L eᵢ = mean ± √3 L eᵢ (L Lᵀ = P_pos, i = 1, 2) with weight
/// 1/6 each. These five points match the Gaussian's moments up to the fourth along each axis, so
/// a track whose 1.7σ ellipse lies under a crown counts as hidden, one half under it as half
/// visible. A P_pos that is not positive definite gives the mean's verdict alone.
double visibleProbability(const Vec2& mean, const Mat2& P_pos, const sensing::Footprint& footprint,
                          const OcclusionMap& map, const CameraOcclusion& camera,
                          const Vec2& sensor, double sensor_height = sensing::kDefaultAltitude);

}  // namespace canopy::agents::tracking
