#pragma once
// The orthographic top-down projection: world metres (y up) ↔ image pixels (y down).
#include <optional>
#include <string_view>

#include "core/types.h"

namespace canopy::render {

struct ImageSize {
  int width = 0;   // px
  int height = 0;  // px
  friend bool operator==(const ImageSize&, const ImageSize&) = default;
};

/// Maps a world rectangle onto an image with square pixels. Pixel coordinates are continuous:
/// (0, 0) is the image's top-left corner, x to the right, y down; pixel (i, j) is the unit square
/// [i, i+1) × [j, j+1) and its centre is (i + ½, j + ½).
struct Viewport {
  ImageSize size;
  Vec2 top_left = Vec2::Zero();  // m, the world point at the image's top-left corner
  double pixel_size = 1.0;       // m per px

  /// The largest scale at which `view` fits the image, centred (aspect preserved).
  static Viewport fit(const Aabb& view, ImageSize size);

  Vec2 toPixel(const Vec2& world) const {
    return {(world.x() - top_left.x()) / pixel_size, (top_left.y() - world.y()) / pixel_size};
  }
  Vec2 toWorld(const Vec2& pixel) const {
    return {top_left.x() + pixel.x() * pixel_size, top_left.y() - pixel.y() * pixel_size};
  }
};

/// Image sides the command line accepts (px).
inline constexpr int kMinImageSide = 16;
inline constexpr int kMaxImageSide = 4096;

/// "WxH" (e.g. "800x600") with both sides in [kMinImageSide, kMaxImageSide]; nullopt otherwise.
std::optional<ImageSize> parseImageSize(std::string_view text);

/// `box` grown by `fraction` of its larger side on every side.
Aabb withMargin(const Aabb& box, double fraction);

/// An image size for `view`: `long_side` px along its longer side, the other side in proportion,
/// both rounded to even numbers (video encoders want even sizes).
ImageSize fitSize(const Aabb& view, int long_side);

}  // namespace canopy::render
