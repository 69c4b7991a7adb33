#pragma once
// A step of a simulation drawn by the CLI's renderer (OSMesa, no trails) into a numpy image: what
// canopy.Simulation.render and canopy.VectorEnv.render share.
#include <pybind11/numpy.h>

#include <cstdint>
#include <optional>

#include "render/canvas.h"
#include "render/image.h"
#include "render/scene_builder.h"
#include "sim/simulation.h"

namespace canopy::python {

class FrameRenderer {
 public:
  /// `sim`'s last step, (height, width, 3) uint8, of the "action" view; a ScenarioError naming
  /// `caller` for a size outside [kMinImageSide, kMaxImageSide]. The scene model is made on the
  /// first call and GL started then (on the calling thread, which must hold the GIL).
  pybind11::array_t<std::uint8_t> render(const sim::Simulation& sim, int width, int height,
                                         const char* caller);

 private:
  std::optional<render::SceneModel> scene_model_;
  std::optional<render::Canvas> canvas_;
  render::Image image_;
};

}  // namespace canopy::python
