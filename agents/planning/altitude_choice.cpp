#include "agents/planning/altitude_choice.h"

#include <algorithm>

namespace canopy::agents::planning {

UavState atAltitude(const UavState& uav, double z) {
  UavState out = uav;
  out.z = z;
  if (!uav.camera) return out;
  out.footprint = sensing::groundFootprint(*uav.camera, z);
  // α(z) = α_ref · ℓ(z) / ℓ(h_ref) at the ground point straight below: z / h_ref.
  out.quality.alpha = uav.reference_alpha * (z / sensing::kDefaultAltitude);
  return out;
}

bool altitudeFree(const UavState& uav) {
  return uav.camera.has_value() && uav.z_min < uav.z_max && uav.climb_rate > 0.0;
}

double footprintGrowth(const UavState& uav, double seconds) {
  if (!altitudeFree(uav) || !(uav.z > 0.0)) return 1.0;
  const double highest = std::min(uav.z_max, uav.z + uav.climb_rate * seconds);  // m
  return std::max(1.0, highest / uav.z);
}

}  // namespace canopy::agents::planning
