#include "render/frame_observer.h"

namespace canopy::render {

render::SceneModel sceneModel(const spec::ScenarioSpec& spec, const Aabb& view) {
  render::SceneModel model;
  model.view = view;
  model.plans = spec.planner.algorithm != agents::PlannerAlgorithm::none;
  model.title = spec.name;
  model.aoi = spec.aoi;
  model.trees = spec.trees;
  for (const spec::UavSpec& uav : spec.uavs) {
    model.contacts = model.contacts || uav.body.radius > 0.0;  // it can touch something
    model.sensors.push_back(uav.sensor);
    model.uav_names.push_back(uav.name);
  }
  for (const spec::TargetSpec& target : spec.targets) model.target_names.push_back(target.name);
  return model;
}

void FrameObserver::onStep(const sim::StepRecord& record) {
  sim::truthSnapshot(record, truth_);
  writer_.onStep(truth_, record.beliefs);
}

}  // namespace canopy::render
