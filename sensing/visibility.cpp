#include "sensing/visibility.h"

#include "sensing/camera.h"
#include "world/world.h"

namespace canopy::sensing {

bool isOccluded(const world::World& world, const Vec2& uav_ground, const Vec2& target,
                OcclusionModel model, double camera_height) {
  if (model == OcclusionModel::canopy) return world.insideOccluder(target);
  if (model == OcclusionModel::volumes)
    return world.sightBlocked(uav_ground, camera_height, target, kTargetHeight);
  return world.firstOccluderOnSegment(uav_ground, target).has_value();
}

bool isVisible(const world::World& world, const Footprint& footprint, const Vec2& uav_ground,
               const Vec2& target, OcclusionModel model) {
  return footprint.contains(target) && !isOccluded(world, uav_ground, target, model);
}

}  // namespace canopy::sensing
