#pragma once
// An 8-bit RGB image in memory, and PNG encoding.
#include <cstdint>
#include <filesystem>
#include <vector>

#include "render/colour.h"
#include "render/viewport.h"

namespace canopy::render {

struct Image {
  ImageSize size;
  std::vector<std::uint8_t> rgb;  // 3 bytes per pixel, rows from the top, no padding

  /// The pixel in column x, row y (from the top); alpha is 255.
  Rgba pixel(int x, int y) const;
};

/// The image as a PNG file's bytes: 8-bit RGB, filter "Sub" on every row, one IDAT chunk
/// compressed by zlib (level 1, run-length strategy). Not stb_image_write: its compressor clamps
/// every level below 5 to 5 and took 22 ms for an 800 × 800 frame, more than the whole frame's
/// 20 ms budget; this takes a few ms for a file of about the same size. Deterministic.
std::vector<std::uint8_t> encodePng(const Image& image);

/// Writes the PNG to `path` through a temporary file and a rename, so that a reader never sees
/// a half-written frame; throws std::runtime_error when it cannot.
void writePng(const std::filesystem::path& path, const Image& image);

}  // namespace canopy::render
