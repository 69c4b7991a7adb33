#pragma once
// Visibility of a target to a UAV (paper eq. 3, algorithms.md §3).
#include "core/enum_names.h"
#include "core/types.h"
#include "sensing/camera.h"
#include "sensing/footprint.h"

namespace canopy::world {
class World;
}

namespace canopy::sensing {

enum class OcclusionModel {
  canopy,         // hidden when strictly inside a tree crown (UAVs looking down)
  line_of_sight,  // hidden when the segment from the UAV's ground point crosses a tree
  volumes,  // hidden when the 3-D segment from the camera to the walker's head crosses a crown's
            // volume (issue 53: crowns and walls with heights, world/tree.h blocksSight)
};
inline constexpr EnumNames<OcclusionModel, 3> kOcclusionModelNames{{
    {OcclusionModel::canopy, "canopy"},
    {OcclusionModel::line_of_sight, "line_of_sight"},
    {OcclusionModel::volumes, "volumes"},
}};

/// True when the target at `target` (m) is inside φ and not occluded under `model`.
bool isVisible(const world::World& world, const Footprint& footprint, const Vec2& uav_ground,
               const Vec2& target, OcclusionModel model);

/// The occlusion half of the test only. Under `volumes` the camera is at camera_height above its
/// ground point and the target's head at kTargetHeight (sensing/camera.h).
bool isOccluded(const world::World& world, const Vec2& uav_ground, const Vec2& target,
                OcclusionModel model, double camera_height = kDefaultAltitude);

}  // namespace canopy::sensing
