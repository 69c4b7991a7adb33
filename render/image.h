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

/// The image as a PNG file's bytes: 8-bit RGB, filter "none" on every row, one IDAT chunk
/// compressed by internal/deflate.h (matches one pixel and one row back, fixed Huffman codes).
/// Deterministic. Not stb_image_write: its compressor clamps every level below 5 to 5 and then
/// compares up to 10 hash-chain candidates of up to 258 bytes at each match; on the benchmark's
/// 800 × 800 frame it took 22 ms (202 kB) with filter "none", 45 ms with its per-row filters,
/// over the whole 20 ms budget. This encoder takes 3.5 ms (227 kB). stb_image decodes its
/// output back to the same pixels (tests/render/canvas_test.cpp).
std::vector<std::uint8_t> encodePng(const Image& image);

/// Writes the PNG to `path` through a temporary file and a rename, so that a reader never sees
/// a half-written frame; throws std::runtime_error when it cannot.
void writePng(const std::filesystem::path& path, const Image& image);

}  // namespace canopy::render
