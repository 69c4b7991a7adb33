#pragma once
// Frames of a run as one more observer of its steps, and what the renderer needs of a scenario.
// Shared by `canopy run --frames` and the Python module (render, run(frames=True)).
#include "render/frame_writer.h"
#include "render/scene_builder.h"
#include "scenarios/spec.h"
#include "scenarios/step_observer.h"
#include "world/snapshot.h"

namespace canopy::app {

/// The scenario as the renderer takes it: name, AOI, trees, sensors and names, drawn in `view`
/// (frame_view.h: viewFor).
render::SceneModel sceneModel(const scenarios::ScenarioSpec& spec, const Aabb& view);

class FrameObserver final : public scenarios::StepObserver {
 public:
  explicit FrameObserver(render::FrameWriter& writer) : writer_(writer) {}
  void onStep(const scenarios::StepRecord& record) override;

 private:
  render::FrameWriter& writer_;
  world::WorldSnapshot truth_;  // the record's truth as the renderer takes it (storage reused)
};

}  // namespace canopy::app
