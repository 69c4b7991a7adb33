#include "app/frame_observer.h"

namespace canopy::app {

render::SceneModel sceneModel(const scenarios::ScenarioSpec& spec, const Aabb& view) {
  render::SceneModel model;
  model.view = view;
  model.plans = spec.planner.algorithm != agents::PlannerAlgorithm::none;
  model.title = spec.name;
  model.aoi = spec.aoi;
  model.trees = spec.trees;
  for (const scenarios::UavSpec& uav : spec.uavs) {
    model.sensors.push_back(uav.sensor);
    model.uav_names.push_back(uav.name);
  }
  for (const scenarios::TargetSpec& target : spec.targets)
    model.target_names.push_back(target.name);
  return model;
}

void FrameObserver::onStep(const scenarios::StepRecord& record) {
  scenarios::truthSnapshot(record, truth_);
  writer_.onStep(truth_, record.beliefs);
}

}  // namespace canopy::app
