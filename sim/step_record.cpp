#include "sim/step_record.h"

namespace canopy::sim {

void truthSnapshot(const StepRecord& record, world::WorldSnapshot& out) {
  out.step = record.step;
  out.time = record.time;
  out.uavs.clear();
  for (const UavRecord& uav : record.uavs)
    out.uavs.push_back(
        {uav.position, uav.velocity, uav.yaw, uav.contacts, uav.contacts_begun, uav.z, uav.climb});
  out.targets.clear();
  for (const TargetRecord& target : record.targets)
    out.targets.push_back({target.position, target.velocity});
}

}  // namespace canopy::sim
