#pragma once
// Visibility of a target to a UAV (paper eq. 3, algorithms.md §3).
#include "core/enum_names.h"
#include "core/types.h"
#include "sensing/footprint.h"

namespace canopy::world {
class World;
}

namespace canopy::sensing {

enum class OcclusionModel {
  canopy,         // hidden when strictly inside a tree crown (UAVs looking down)
  line_of_sight,  // hidden when the segment from the UAV's ground point crosses a tree
};
inline constexpr EnumNames<OcclusionModel, 2> kOcclusionModelNames{{
    {OcclusionModel::canopy, "canopy"},
    {OcclusionModel::line_of_sight, "line_of_sight"},
}};

/// True when the target at `target` (m) is inside φ and not occluded under `model`.
bool isVisible(const world::World& world, const Footprint& footprint, const Vec2& uav_ground,
               const Vec2& target, OcclusionModel model);

/// The occlusion half of the test only.
bool isOccluded(const world::World& world, const Vec2& uav_ground, const Vec2& target,
                OcclusionModel model);

}  // namespace canopy::sensing
