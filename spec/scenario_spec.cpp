#include "spec/scenario_spec.h"

#include <cmath>

namespace canopy::spec {

int ScenarioSpec::steps() const {
  return static_cast<int>(std::lround(duration / dt));
}

world::WorldDef ScenarioSpec::worldDef() const {
  world::WorldDef def;
  def.aoi = aoi;
  for (const UavSpec& uav : uavs) def.uavs.push_back(uav.body);
  for (const TargetSpec& target : targets) def.targets.push_back({target.path});
  def.trees = trees;
  return def;
}

std::vector<sensing::LabelId> ScenarioSpec::targetLabels() const {
  std::vector<sensing::LabelId> labels_of;
  for (const TargetSpec& target : targets) labels_of.push_back(target.label);
  return labels_of;
}

}  // namespace canopy::spec
