#include "render/image.h"

#include <zlib.h>

#include <array>
#include <cstring>
#include <span>
#include <stdexcept>
#include <string_view>

#include "core/text_file.h"

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
  const std::span<const std::uint8_t> crc_input = std::span(png).subspan(start);
  putBigEndian(png, static_cast<std::uint32_t>(
                        ::crc32(0, crc_input.data(), static_cast<uInt>(crc_input.size()))));
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
  // Each row is preceded by its filter type, 1 ("Sub": each byte minus the byte of the pixel to
  // its left, PNG §9.2): flat colour becomes runs of zeros, which zlib's run-length strategy
  // compresses quickly.
  const std::size_t row = 3 * w + 1;
  std::vector<std::uint8_t> raw(row * h);
  for (std::size_t y = 0; y < h; ++y) {
    const std::uint8_t* in = &image.rgb[y * 3 * w];
    std::uint8_t* out = &raw[y * row];
    out[0] = 1;
    for (std::size_t i = 0; i < 3 * w; ++i) {
      out[1 + i] = static_cast<std::uint8_t>(in[i] - (i >= 3 ? in[i - 3] : 0));
    }
  }
  std::vector<std::uint8_t> header;
  putBigEndian(header, static_cast<std::uint32_t>(w));
  putBigEndian(header, static_cast<std::uint32_t>(h));
  header.insert(header.end(),
                {8, 2, 0, 0, 0});  // 8 bits, RGB, deflate, adaptive filters, no interlace

  std::vector<std::uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  chunk(png, "IHDR", header);
  std::vector<std::uint8_t> compressed(compressBound(static_cast<uLong>(raw.size())));
  z_stream stream{};
  if (deflateInit2(&stream, Z_BEST_SPEED, Z_DEFLATED, 15, 8, Z_RLE) != Z_OK) {
    throw std::runtime_error("encodePng: zlib failed");
  }
  stream.next_in = raw.data();
  stream.avail_in = static_cast<uInt>(raw.size());
  stream.next_out = compressed.data();
  stream.avail_out = static_cast<uInt>(compressed.size());
  const int status = deflate(&stream, Z_FINISH);
  deflateEnd(&stream);
  if (status != Z_STREAM_END) throw std::runtime_error("encodePng: zlib failed");
  compressed.resize(stream.total_out);
  chunk(png, "IDAT", compressed);
  chunk(png, "IEND", {});
  return png;
}

void writePng(const std::filesystem::path& path, const Image& image) {
  const std::vector<std::uint8_t> png = encodePng(image);
  writeFileAtomically(path, std::string(png.begin(), png.end()));
}

}  // namespace canopy::render
