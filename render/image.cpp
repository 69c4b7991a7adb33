#include "render/image.h"

#include <array>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string_view>

#include "render/internal/deflate.h"

namespace canopy::render {
namespace {

void putBigEndian(std::vector<std::uint8_t>& out, std::uint32_t value) {
  for (const int shift : {24, 16, 8, 0}) out.push_back(static_cast<std::uint8_t>(value >> shift));
}

// A PNG chunk: length, type, data, CRC-32 of type and data (PNG §5.3).
void chunk(std::vector<std::uint8_t>& png, std::string_view type,
           std::span<const std::uint8_t> data) {
  putBigEndian(png, static_cast<std::uint32_t>(data.size()));
  const std::size_t start = png.size();
  png.insert(png.end(), type.begin(), type.end());
  png.insert(png.end(), data.begin(), data.end());
  putBigEndian(png, internal::crc32(std::span(png).subspan(start)));
}

}  // namespace

Rgba Image::pixel(int x, int y) const {
  const std::uint8_t* p = rgb.data() + (static_cast<std::size_t>(y) * size.width + x) * 3;
  return {p[0], p[1], p[2], 255};
}

std::vector<std::uint8_t> encodePng(const Image& image) {
  const auto w = static_cast<std::size_t>(image.size.width),
             h = static_cast<std::size_t>(image.size.height);
  if (w == 0 || h == 0 || image.rgb.size() != w * h * 3)
    throw std::invalid_argument("encodePng: bad image");
  // Each row is preceded by its filter type, 0 ("none").
  const std::size_t row = 3 * w + 1;
  std::vector<std::uint8_t> raw(row * h);
  for (std::size_t y = 0; y < h; ++y) {
    raw[y * row] = 0;
    std::memcpy(&raw[y * row + 1], &image.rgb[y * 3 * w], 3 * w);
  }
  std::vector<std::uint8_t> header;
  putBigEndian(header, static_cast<std::uint32_t>(w));
  putBigEndian(header, static_cast<std::uint32_t>(h));
  header.insert(header.end(),
                {8, 2, 0, 0, 0});  // 8 bits, RGB, deflate, adaptive filters, no interlace

  std::vector<std::uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  chunk(png, "IHDR", header);
  chunk(png, "IDAT", internal::zlibCompress(raw, 3, row));
  chunk(png, "IEND", {});
  return png;
}

void writePng(const std::filesystem::path& path, const Image& image) {
  const std::vector<std::uint8_t> png = encodePng(image);
  std::filesystem::path temporary = path;
  temporary += ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
    if (!out) throw std::runtime_error("cannot write " + temporary.string());
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) throw std::runtime_error("cannot write " + path.string() + ": " + error.message());
}

}  // namespace canopy::render
