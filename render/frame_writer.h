#pragma once
// Frames of a run: DIR/frame_NNNNNN.png (or .svg, .pdf) every K steps (NNNNNN = the step index
// k).
#include <filesystem>
#include <span>

#include "agents/belief.h"
#include "render/canvas.h"
#include "render/scene_vector.h"
#include "render/scene_builder.h"
#include "render/trails.h"
#include "world/snapshot.h"

namespace canopy::render {

/// Long side (px) of a frame when no size is given.
inline constexpr int kDefaultFrameLongSide = 800;

/// What a frame is written as: a PNG through the canvas (OSMesa), or the same scene as a vector
/// document through cairo (render/scene_vector.h), which starts no GL.
enum class FrameFormat { png, svg, pdf };

/// "png", "svg" or "pdf": the frames' file extension without the dot.
const char* frameExtension(FrameFormat format);

struct FrameOptions {
  std::filesystem::path dir;  // where the frames go (created)
  int every = 1;              // K ≥ 1: a frame at every step k with k mod K = 0
  ImageSize size;             // px; {0, 0}: defaultFrameSize(aoi)
  FrameFormat format = FrameFormat::png;
  SceneOptions scene;
};

/// kDefaultFrameLongSide px along the longer side of the AOI (with the frame's margin).
ImageSize defaultFrameSize(const Aabb& aoi, const SceneOptions& scene = {});

class FrameWriter {
 public:
  /// Creates `options.dir` and deletes stale frame_*.png, .svg and .pdf files in it, so that a
  /// video or a folder of frames never mixes two runs; starts no GL (the canvas starts it with the first frame). Throws WriteError when
  /// the directory cannot be made or is a symbolic link, std::invalid_argument for a bad size.
  FrameWriter(SceneModel model, FrameOptions options);

  /// Call after every step: extends the trails, and on frame steps renders and writes a frame.
  void onStep(const world::WorldSnapshot& truth, std::span<const agents::AgentBelief> beliefs);

  int framesWritten() const { return frames_written_; }
  ImageSize size() const { return canvas_.size(); }
  const std::filesystem::path& dir() const { return options_.dir; }

  /// dir/frame_NNNNNN.EXT for step k (six digits at least; EXT from the format).
  static std::filesystem::path framePath(const std::filesystem::path& dir, int step,
                                         FrameFormat format = FrameFormat::png);

 private:
  SceneModel model_;
  FrameOptions options_;
  TargetTrails trails_;
  Canvas canvas_;
  Image image_;
  int frames_written_ = 0;
};

}  // namespace canopy::render
