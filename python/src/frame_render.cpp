#include "python/src/frame_render.h"

#include <algorithm>
#include <string>

#include "render/frame_observer.h"
#include "render/frame_view.h"
#include "render/viewport.h"
#include "sim/step_record.h"
#include "spec/error.h"

namespace py = pybind11;

namespace canopy::python {

py::array_t<std::uint8_t> FrameRenderer::render(const sim::Simulation& sim, int width, int height,
                                                const char* caller) {
  if (width < render::kMinImageSide || width > render::kMaxImageSide ||
      height < render::kMinImageSide || height > render::kMaxImageSide) {
    throw spec::ScenarioError(caller, "width, height",
                              "expected width and height in [" +
                                  std::to_string(render::kMinImageSide) + ", " +
                                  std::to_string(render::kMaxImageSide) + "] px, got " +
                                  std::to_string(width) + " x " + std::to_string(height));
  }
  const render::ImageSize size{width, height};
  if (!scene_model_)
    scene_model_ = render::sceneModel(sim.spec(), render::viewFor("action", sim.spec()));
  if (!canvas_ || canvas_->size() != size) canvas_.emplace(size);
  const sim::StepRecord& record = sim.lastStep();
  world::WorldSnapshot truth;
  sim::truthSnapshot(record, truth);
  const render::Scene scene =
      render::buildScene(*scene_model_, truth, record.beliefs, render::TargetTrails{}, size);
  canvas_->draw(scene, image_);
  py::array_t<std::uint8_t> out({height, width, 3});
  std::copy(image_.rgb.begin(), image_.rgb.end(), out.mutable_data());
  return out;
}

}  // namespace canopy::python
