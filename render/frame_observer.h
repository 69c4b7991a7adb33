#pragma once
// Frames of a run as one more observer of its steps, and what the renderer needs of a scenario.
// Shared by `canopy run --frames` and the Python module (render, run(frames=True)).
#include "render/frame_writer.h"
#include "render/scene_builder.h"
#include "sim/step_observer.h"
#include "spec/scenario_spec.h"
#include "world/snapshot.h"

namespace canopy::render {

/// The scenario as the renderer takes it: name, AOI, trees, sensors and names, drawn in `view`
/// (frame_view.h: viewFor).
render::SceneModel sceneModel(const spec::ScenarioSpec& spec, const Aabb& view);

class FrameObserver final : public sim::StepObserver {
 public:
  explicit FrameObserver(render::FrameWriter& writer) : writer_(writer) {}
  void onStep(const sim::StepRecord& record) override;

 private:
  render::FrameWriter& writer_;
  world::WorldSnapshot truth_;  // the record's truth as the renderer takes it (storage reused)
};

}  // namespace canopy::render
