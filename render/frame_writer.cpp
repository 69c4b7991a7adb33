#include "render/frame_writer.h"

#include <cstdio>
#include <stdexcept>
#include <string>

#include "core/output_file.h"
#include "core/text_file.h"
#include "render/image.h"

namespace canopy::render {
namespace {

ImageSize chosenSize(const SceneModel& model, const FrameOptions& options) {
  return options.size.width > 0 && options.size.height > 0
             ? options.size
             : defaultFrameSize(model.shown(), options.scene);
}

}  // namespace

const char* frameExtension(FrameFormat format) {
  switch (format) {
    case FrameFormat::svg:
      return "svg";
    case FrameFormat::pdf:
      return "pdf";
    case FrameFormat::png:
      break;
  }
  return "png";
}

ImageSize defaultFrameSize(const Aabb& aoi, const SceneOptions& scene) {
  return fitSize(withMargin(aoi, scene.margin), kDefaultFrameLongSide);
}

FrameWriter::FrameWriter(SceneModel model, FrameOptions options)
    : model_(std::move(model)),
      options_(std::move(options)),
      canvas_(chosenSize(model_, options_)) {
  if (options_.every < 1) throw std::invalid_argument("FrameWriter: every must be >= 1");
  // The frames directory itself must not be a link: stale frames are deleted in it.
  makeOutputDirectories(options_.dir, options_.dir.parent_path());
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(options_.dir, error)) {
    const std::string name = entry.path().filename().string();
    const std::string extension = entry.path().extension().string();
    if (name.starts_with("frame_") &&
        (extension == ".png" || extension == ".svg" || extension == ".pdf")) {
      std::filesystem::remove(entry.path(), error);
    }
  }
}

std::filesystem::path FrameWriter::framePath(const std::filesystem::path& dir, int step,
                                             FrameFormat format) {
  char name[40];
  std::snprintf(name, sizeof name, "frame_%06d.%s", step, frameExtension(format));
  return dir / name;
}

void FrameWriter::onStep(const world::WorldSnapshot& truth,
                         std::span<const agents::AgentBelief> beliefs) {
  trails_.add(truth);
  if (truth.step % options_.every != 0) return;
  const Scene scene = buildScene(model_, truth, beliefs, trails_, canvas_.size(), options_.scene);
  const std::filesystem::path path = framePath(options_.dir, truth.step, options_.format);
  if (options_.format == FrameFormat::png) {
    canvas_.draw(scene, image_);
    writePng(path, image_);
  } else {
    writeFileAtomically(path, sceneToVector(scene, options_.format == FrameFormat::svg
                                                       ? VectorFormat::svg
                                                       : VectorFormat::pdf));
  }
  ++frames_written_;
}

}  // namespace canopy::render
