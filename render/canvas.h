#pragma once
// The OSMesa canvas: the only GL code in canopy. Offscreen, CPU only (Mesa's llvmpipe): no
// display, no X server, no GPU. The GL context is created on the first draw, never before, so
// that a run that writes no frames never starts GL.
#include <cstdint>
#include <memory>
#include <vector>

#include "render/image.h"
#include "render/scene.h"

namespace canopy::render {

/// Anti-aliasing is analytic, per fragment (the programmable form of GL smoothing): discs,
/// rings and lines get the coverage of each pixel from its distance to their edges, a one-pixel
/// ramp. Polygons and text are drawn aliased; every polygon a frame shows is outlined by an
/// anti-aliased line, and text sits on whole pixels. 2 × 2 supersampling (tried first) looked
/// the same and took 1.8× the CPU in llvmpipe: four times the pixels to clear, shade and filter.
///
/// Largest image side (px) the canvas accepts.
inline constexpr int kMaxCanvasSide = 8192;

class Canvas {
 public:
  /// size: the image (px). Throws std::invalid_argument when a side is below 1 or above
  /// kMaxCanvasSide. Creates no GL context.
  explicit Canvas(ImageSize size);
  ~Canvas();
  Canvas(Canvas&&) noexcept;
  Canvas& operator=(Canvas&&) noexcept;
  Canvas(const Canvas&) = delete;
  Canvas& operator=(const Canvas&) = delete;

  ImageSize size() const { return size_; }

  /// Draws the scene (alpha blending over its background) into `out`.
  /// scene.viewport.size must equal size(). Throws std::runtime_error if GL cannot start.
  void draw(const Scene& scene, Image& out);
  Image draw(const Scene& scene);

  /// Mask pass: draws the scene's triangles with additive blending into a black buffer, without
  /// anti-aliasing. Returns, per pixel (rows from the top), the sum of the red components of the
  /// shapes that contain the pixel's centre, saturating at 255.
  const std::vector<std::uint8_t>& accumulate(const Scene& scene);

 private:
  struct Gl;
  Gl& gl();  // the GL state, created on first use

  ImageSize size_;
  std::unique_ptr<Gl> gl_;
  std::vector<std::uint8_t> mask_;
};

/// GL contexts created by this process so far (for tests: a run without frames creates none).
int glContextsCreated();

}  // namespace canopy::render
